// Cover a W×H raster with a 2^n+1 square by mirroring it, and crop back.
#pragma once

#include <cstdint>

#include "common/grid.hpp"

namespace mcmd {

// Reflect index i into [0, len) without repeating the edge cell
// (-1 -> 1, len -> len - 2), repeating as needed. Pre: len >= 1. Inline
// for the common case, an index already in range (the coarse guide's 4×4
// taps: 20 per cell it is read at, and a 64-bit modulo each was ~5 ms of a
// 1201² blob fill).
int reflect_out_of_range(long long i, int len);
inline int reflect_index(long long i, int len) {
  return i >= 0 && i < len ? static_cast<int>(i) : reflect_out_of_range(i, len);
}

// Smallest n with 2^n + 1 >= max(w, h). Pre: w, h >= 1.
int levels_to_cover(int w, int h);

// A 2^n+1 grid whose cell (x, y) holds raster cell (x0 + x, y0 + y)
// reflected into range, `known` where valid[...] != 0. With the origin at 0
// and n >= levels_to_cover(w, h) it covers the raster; another origin or a
// smaller n gives a square window of the mirrored raster.
Grid mirror_padded_grid(const double* z, const std::uint8_t* valid, int w, int h, int n, int x0 = 0, int y0 = 0);

}  // namespace mcmd
