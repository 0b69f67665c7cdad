// One pass over a raster of any size in bounded memory: full-width strips of
// about a million cells, top to bottom.
#pragma once

#include <algorithm>
#include <cstdint>
#include <vector>

#include "mcmd/raster_access.hpp"

namespace mcmd::detail {

// Calls f(y0, rows, z, valid) for each strip in order; z and valid hold the
// strip's rows × raster.width cells, row-major.
template <class F>
void for_each_strip(const RasterAccess& raster, F&& f) {
  const int rows = std::clamp((1 << 20) / raster.width, 1, raster.height);
  std::vector<double> z(static_cast<std::size_t>(raster.width) * rows);
  std::vector<std::uint8_t> valid(z.size());
  for (int y0 = 0; y0 < raster.height; y0 += rows) {
    const int h = std::min(rows, raster.height - y0);
    raster.read(0, y0, raster.width, h, z.data(), valid.data());
    f(y0, h, static_cast<const double*>(z.data()), static_cast<const std::uint8_t*>(valid.data()));
  }
}

}  // namespace mcmd::detail
