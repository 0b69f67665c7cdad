// An in-memory raster for the raster engine's tests: reads return the
// original, writes go to `out`, with counts of what was written.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <gtest/gtest.h>
#include <limits>
#include <vector>

#include "mcmd/raster_access.hpp"
#include "test_terrain.hpp"

namespace mcmd::test {

struct MemRaster {
  int w = 0, h = 0;
  std::vector<double> z, out;
  std::vector<std::uint8_t> valid;
  std::size_t known_writes = 0;  // writes to known cells (must stay 0)
  std::size_t writes = 0;        // cells written
  std::vector<int> write_count;  // per cell

  MemRaster(int w_, int h_) : w(w_), h(h_) {
    const std::size_t n = static_cast<std::size_t>(w) * h;
    z.assign(n, 0.0);
    valid.assign(n, 1);
    write_count.assign(n, 0);
  }
  std::size_t at(int x, int y) const { return static_cast<std::size_t>(y) * w + x; }

  RasterAccess access() {
    out = z;
    for (std::size_t i = 0; i < out.size(); ++i)
      if (!valid[i]) out[i] = std::numeric_limits<double>::quiet_NaN();
    RasterAccess a;
    a.width = w;
    a.height = h;
    a.read = [this](int x0, int y0, int rw, int rh, double* zz, std::uint8_t* vv) {
      EXPECT_TRUE(x0 >= 0 && y0 >= 0 && x0 + rw <= w && y0 + rh <= h);
      for (int y = 0; y < rh; ++y)
        for (int x = 0; x < rw; ++x) {
          zz[static_cast<std::size_t>(y) * rw + x] = z[at(x0 + x, y0 + y)];
          vv[static_cast<std::size_t>(y) * rw + x] = valid[at(x0 + x, y0 + y)];
        }
    };
    a.write = [this](int x0, int y0, int rw, int rh, const double* zz, const std::uint8_t* m) {
      EXPECT_TRUE(x0 >= 0 && y0 >= 0 && x0 + rw <= w && y0 + rh <= h);
      for (int y = 0; y < rh; ++y)
        for (int x = 0; x < rw; ++x) {
          if (!m[static_cast<std::size_t>(y) * rw + x]) continue;
          const std::size_t i = at(x0 + x, y0 + y);
          if (valid[i]) ++known_writes;
          ++writes;
          ++write_count[i];
          out[i] = zz[static_cast<std::size_t>(y) * rw + x];
        }
    };
    return a;
  }
  std::size_t voids() const { return static_cast<std::size_t>(std::count(valid.begin(), valid.end(), 0)); }
  bool complete() const {
    return std::all_of(out.begin(), out.end(), [](double v) { return std::isfinite(v); });
  }
};

inline double terrain(int x, int y) {
  return 800.0 + 300.0 * std::sin(x * 0.021) * std::cos(y * 0.017) + 120.0 * std::sin(0.05 * x + 0.03 * y) +
         0.8 * x - 0.5 * y;
}

// Terrain everywhere, no void.
inline MemRaster terrain_raster(int w, int h) {
  MemRaster r(w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) r.z[r.at(x, y)] = terrain(x, y);
  return r;
}

// Terrain everywhere, then voids: discs and scattered cells (hash under `drop`).
inline MemRaster make_raster(int w, int h, double drop = 0.05) {
  MemRaster r(w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      r.z[r.at(x, y)] = terrain(x, y);
      const bool dropped = (hash_uniform(11, x, y) + 1.0) / 2.0 < drop;
      const bool disc = std::hypot(x - 0.4 * w, y - 0.6 * h) < 0.12 * std::max(w, h);
      if (dropped || disc) r.valid[r.at(x, y)] = 0;
    }
  if (r.voids() == r.valid.size()) r.valid[0] = 1;
  return r;
}

inline void punch_disc(MemRaster& r, double cx, double cy, double radius) {
  for (int y = 0; y < r.h; ++y)
    for (int x = 0; x < r.w; ++x)
      if (std::hypot(x - cx, y - cy) <= radius) r.valid[r.at(x, y)] = 0;
}

}  // namespace mcmd::test
