// The part of a raster the roughness is made for (a field or a window).
#pragma once

#include <cstddef>
#include <cstdint>

#include "common/grid.hpp"

namespace mcmd {

// A w×h part of a raster (row-major) whose cell (0, 0) is raster cell (x0, y0):
// the noise is keyed on raster coordinates, so any window or field of a
// raster sees the same noise. Unknown cells are the non-constraint ones; the
// noise is made for those flagged in `wanted` (null: all of them). `depth`
// bounds the distance from any unknown cell to a constraint (< 0: unknown).
struct RoughField {
  int w = 0, h = 0;
  long long x0 = 0, y0 = 0;
  const double* z = nullptr;
  const CellState* state = nullptr;
  const std::uint8_t* wanted = nullptr;
  double depth = -1.0;
  std::size_t cells() const { return static_cast<std::size_t>(w) * static_cast<std::size_t>(h); }
  std::size_t index(int x, int y) const { return static_cast<std::size_t>(y) * static_cast<std::size_t>(w) + x; }
  static RoughField of(const Grid& g) {
    return RoughField{g.side(), g.side(), g.origin_x(), g.origin_y(), g.elevations().data(), g.states().data()};
  }
};

}  // namespace mcmd
