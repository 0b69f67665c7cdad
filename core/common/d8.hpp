// The eight neighbours of a raster cell (D8), clockwise from the east, as
// the morphology and the erosion walk them; odd directions are diagonal.
#pragma once

#include <array>
#include <cmath>
#include <cstdint>

namespace mcmd::d8 {

// The steps to the neighbours.
inline constexpr int kDx[8] = {1, 1, 0, -1, -1, -1, 0, 1};
inline constexpr int kDy[8] = {0, 1, 1, 1, 0, -1, -1, -1};

// 1 / the step's length in cells: a drop over the step, times this, is its slope.
inline constexpr double kPerStep[8] = {1.0, M_SQRT1_2, 1.0, M_SQRT1_2, 1.0, M_SQRT1_2, 1.0, M_SQRT1_2};

// The step's length in cells: 1, or √2 on a diagonal.
inline constexpr double length(int k) { return k & 1 ? M_SQRT2 : 1.0; }

// Index offsets of an interior cell's neighbours in a w-wide field (no
// bounds: the caller keeps off the border).
inline std::array<std::int32_t, 8> offsets(int w) { return {1, w + 1, w, w - 1, -1, -w - 1, -w, -w + 1}; }

}  // namespace mcmd::d8
