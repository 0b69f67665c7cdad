// One pass over a raster of any size in bounded memory: full-width strips of
// about a million cells, top to bottom.
#pragma once

#include <algorithm>
#include <cstdint>
#include <future>
#include <utility>
#include <vector>

#include "mcmd/raster_access.hpp"

namespace mcmd::detail {

// Rows per strip: about a million cells.
inline int strip_rows(const RasterAccess& raster) { return std::clamp((1 << 20) / raster.width, 1, raster.height); }

// Calls f(y0, rows, z, valid) for each strip in order; z and valid hold the
// strip's rows × raster.width cells, row-major.
template <class F>
void for_each_strip(const RasterAccess& raster, F&& f) {
  const int rows = strip_rows(raster);
  std::vector<double> z(static_cast<std::size_t>(raster.width) * rows);
  std::vector<std::uint8_t> valid(z.size());
  for (int y0 = 0; y0 < raster.height; y0 += rows) {
    const int h = std::min(rows, raster.height - y0);
    raster.read(0, y0, raster.width, h, z.data(), valid.data());
    f(y0, h, static_cast<const double*>(z.data()), static_cast<const std::uint8_t*>(valid.data()));
  }
}

// for_each_strip with the reading and the work overlapped: f runs on a helper
// thread while the calling thread reads the next strip (reads stay on the
// caller's thread, as RasterAccess asks), then after(y_end) runs on the
// caller's thread (progress). f must not touch `raster`; calls of f never
// overlap each other, so f needs no lock. Worth it where both halves cost:
// the tiled fill's first pass (GDAL's decode and conversion, then the scan).
template <class F, class After>
void for_each_strip_overlapped(const RasterAccess& raster, F&& f, After&& after) {
  struct Strip {
    std::vector<double> z;
    std::vector<std::uint8_t> valid;
  };
  const int rows = strip_rows(raster);
  const std::size_t cells = static_cast<std::size_t>(raster.width) * rows;
  Strip a{std::vector<double>(cells), std::vector<std::uint8_t>(cells)};
  Strip b = a;
  std::future<void> working;  // declared after the strips: a throw waits for f before they go
  int working_end = 0;
  for (int y0 = 0; y0 < raster.height; y0 += rows) {
    const int h = std::min(rows, raster.height - y0);
    raster.read(0, y0, raster.width, h, a.z.data(), a.valid.data());
    if (working.valid()) {
      working.get();  // rethrows what f threw
      after(working_end);
    }
    std::swap(a, b);  // b: the strip just read, for f; a: free for the next read
    working = std::async(std::launch::async, [&f, &b, y0, h] {
      f(y0, h, static_cast<const double*>(b.z.data()), static_cast<const std::uint8_t*>(b.valid.data()));
    });
    working_end = y0 + h;
  }
  if (working.valid()) {
    working.get();
    after(working_end);
  }
}

}  // namespace mcmd::detail
