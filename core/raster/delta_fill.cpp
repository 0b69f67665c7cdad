#include "mcmd/delta_fill.hpp"

#include <algorithm>
#include <cmath>
#include <unordered_map>
#include <vector>

#include "common/distance.hpp"
#include "mcmd/fill_raster.hpp"
#include "raster/strips.hpp"

namespace mcmd {

namespace {

// Lags at which D's autocorrelation is measured, in cells.
constexpr int kLags[] = {1, 2, 3, 4, 6, 8, 12, 16, 24, 32, 48, 64, 96, 128};
constexpr int kLagCount = sizeof(kLags) / sizeof(kLags[0]);

// What a first read of the raster and the second DEM says.
struct Survey {
  double lo = 0, hi = 0;            // the known elevations' range
  std::size_t known = 0;
  std::size_t voids_without_s = 0;  // void cells the second DEM has no value for
  double sums[kLagCount][6] = {};   // per lag: n, Σa, Σb, Σa², Σb², Σab

  void add_row(const double* z, const std::uint8_t* valid, const double* s, int w, bool sample) {
    for (int x = 0; x < w; ++x) {
      if (!valid[x]) {
        voids_without_s += std::isnan(s[x]);
        continue;
      }
      lo = known ? std::min(lo, z[x]) : z[x];
      hi = known ? std::max(hi, z[x]) : z[x];
      ++known;
    }
    if (!sample) return;
    for (int k = 0; k < kLagCount; ++k)
      for (int x = 0; x + kLags[k] < w; ++x) {
        const int y = x + kLags[k];
        if (!valid[x] || !valid[y] || std::isnan(s[x]) || std::isnan(s[y])) continue;
        const double a = z[x] - s[x], b = z[y] - s[y];
        double* t = sums[k];
        t[0] += 1, t[1] += a, t[2] += b, t[3] += a * a, t[4] += b * b, t[5] += a * b;
      }
  }

  // The lag where the autocorrelation of D falls below 1/e (interpolated);
  // the longest lag when it never does, 1 when D cannot be measured.
  double correlation_length() const {
    double previous_lag = 0, previous_r = 1;
    for (int k = 0; k < kLagCount; ++k) {
      const double* t = sums[k];
      if (t[0] < 16) return 1.0;
      const double cov = t[5] / t[0] - (t[1] / t[0]) * (t[2] / t[0]);
      const double va = t[3] / t[0] - (t[1] / t[0]) * (t[1] / t[0]);
      const double vb = t[4] / t[0] - (t[2] / t[0]) * (t[2] / t[0]);
      if (va <= 0 || vb <= 0) return 1.0;
      const double r = cov / std::sqrt(va * vb);
      if (r < 1 / M_E)
        return previous_lag + (kLags[k] - previous_lag) * (previous_r - 1 / M_E) / (previous_r - r);
      previous_lag = kLags[k], previous_r = r;
    }
    return kLags[kLagCount - 1];
  }
};

Survey survey(const RasterAccess& raster, const Background& second) {
  Survey out;
  const int w = raster.width;
  std::vector<double> s;
  detail::for_each_strip(raster, [&](int y0, int rows, const double* z, const std::uint8_t* valid) {
    s.resize(static_cast<std::size_t>(w) * rows);
    second.read(0, y0, w, rows, s.data());
    for (int r = 0; r < rows; ++r) {
      const std::size_t at = static_cast<std::size_t>(r) * w;
      out.add_row(z + at, valid + at, s.data() + at, w, (y0 + r) % 4 == 0);
    }
  });
  return out;
}

// Filled values of some void cells, by raster index.
using CellValues = std::unordered_map<std::size_t, double>;

// Fill `raster` and keep what it writes to the void cells where the second
// DEM has a value (`with_s`) or has none.
CellValues fill_and_keep(const RasterAccess& raster, const Background& second, bool with_s, const FillParams& params,
                         const TilingParams& tiling, const ProgressFn& progress) {
  CellValues cells;
  RasterAccess capture = raster;
  capture.write = [&](int x0, int y0, int w, int h, const double* z, const std::uint8_t* mask) {
    std::vector<double> s(static_cast<std::size_t>(w) * h);
    second.read(x0, y0, w, h, s.data());
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        const std::size_t i = static_cast<std::size_t>(y) * w + x;
        if (mask[i] && std::isnan(s[i]) != with_s)
          cells[static_cast<std::size_t>(y0 + y) * raster.width + (x0 + x)] = z[i];
      }
  };
  fill_raster(capture, params, tiling, progress);
  return cells;
}

// The raster of differences D = z − s (0 at known cells the second DEM has
// no value for: no correction is known there); writes go to `raster` as they are.
RasterAccess differences(const RasterAccess& raster, const Background& second) {
  RasterAccess d = raster;
  d.read = [&raster, &second](int x0, int y0, int w, int h, double* z, std::uint8_t* valid) {
    raster.read(x0, y0, w, h, z, valid);
    std::vector<double> s(static_cast<std::size_t>(w) * h);
    second.read(x0, y0, w, h, s.data());
    for (std::size_t i = 0; i < s.size(); ++i)
      if (valid[i]) z[i] = std::isnan(s[i]) ? 0.0 : z[i] - s[i];
  };
  return d;
}

// The distance from each cell of a w×h rectangle at (x0, y0) to the nearest
// known cell, exact up to `halo` (farther: more than `halo`).
std::vector<double> rim_distance(const RasterAccess& raster, int x0, int y0, int w, int h, int halo) {
  const int gx0 = std::max(0, x0 - halo), gy0 = std::max(0, y0 - halo);
  const int gw = std::min(raster.width, x0 + w + halo) - gx0, gh = std::min(raster.height, y0 + h + halo) - gy0;
  std::vector<double> gz(static_cast<std::size_t>(gw) * gh);
  std::vector<std::uint8_t> gvalid(gz.size());
  raster.read(gx0, gy0, gw, gh, gz.data(), gvalid.data());
  const std::vector<double> grown = distance_to_valid(gvalid.data(), gw, gh);
  std::vector<double> dist(static_cast<std::size_t>(w) * h);
  for (int y = 0; y < h; ++y)
    std::copy_n(grown.begin() + static_cast<std::size_t>(y + y0 - gy0) * gw + (x0 - gx0), w,
                dist.begin() + static_cast<std::size_t>(y) * w);
  return dist;
}

// The differences, whose filled voids are written to `raster` as
// s + D·fade, or, with the smooth D of a rough fill, as
// s + D − (1 − fade)·D_smooth (the relief is not faded); the plain fill where
// s has no value.
RasterAccess delta_surface(const RasterAccess& raster, const Background& second, double fade_length,
                           const CellValues& plain, const CellValues* smooth) {
  RasterAccess d = differences(raster, second);
  d.write = [&raster, &second, fade_length, &plain, smooth](int x0, int y0, int w, int h, const double* dz,
                                                              const std::uint8_t* mask) {
    const int halo = static_cast<int>(std::ceil(10 * fade_length)) + 1;
    const std::vector<double> dist = rim_distance(raster, x0, y0, w, h, halo);
    std::vector<double> s(dist.size()), out(dist.size());
    std::vector<std::uint8_t> m(mask, mask + dist.size());
    second.read(x0, y0, w, h, s.data());
    for (std::size_t i = 0; i < dist.size(); ++i) {
      if (!m[i]) continue;
      const std::size_t cell = static_cast<std::size_t>(y0 + i / w) * raster.width + (x0 + i % w);
      if (std::isnan(s[i])) {
        const auto it = plain.find(cell);
        m[i] = it != plain.end();
        out[i] = m[i] ? it->second : 0.0;
        continue;
      }
      const double fade = dist[i] > halo ? 0.0 : std::exp(-std::max(0.0, dist[i] - 1) / fade_length);
      const auto it = smooth ? smooth->find(cell) : CellValues::const_iterator{};
      out[i] = smooth && it != smooth->end() ? s[i] + dz[i] - (1 - fade) * it->second : s[i] + dz[i] * fade;
    }
    raster.write(x0, y0, w, h, out.data(), m.data());
  };
  return d;
}

}  // namespace

void fill_raster_from(const RasterAccess& raster, const Background& second, const FillParams& params,
                      const TilingParams& tiling, const ProgressFn& progress, const RasterFillHooks& hooks) {
  const Survey survey_ = survey(raster, second);
  FillParams p = params;
  // Roughness in units of the terrain's own range, not of the differences'.
  if (p.noise_unit <= 0 && survey_.known > 0) p.noise_unit = survey_.hi - survey_.lo;
  const double fade_length = std::clamp(std::max(second.cell_ratio, survey_.correlation_length()), 1.0, 256.0);
  // Up to three passes: the plain fill where s has no value, the smooth
  // differences under a rough fill, and the fill itself.
  const bool rough = adds_roughness(p);
  const int passes = 1 + (survey_.voids_without_s > 0) + rough;
  int pass = 0;
  const auto next = [&] {
    const double lo = static_cast<double>(pass) / passes;
    return sub_progress(progress, lo, static_cast<double>(++pass) / passes);
  };
  CellValues plain, smooth;
  if (survey_.voids_without_s > 0) plain = fill_and_keep(raster, second, false, params, tiling, next());
  if (rough) {
    FillParams flat = p;
    flat.rs = 0, flat.rs_auto = false;
    smooth = fill_and_keep(differences(raster, second), second, true, flat, tiling, next());
  }
  fill_raster(delta_surface(raster, second, fade_length, plain, rough ? &smooth : nullptr), p, tiling, next(), hooks);
}

}  // namespace mcmd
