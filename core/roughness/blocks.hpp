// The block lattice and areas the roughness works on (internal to roughness/).
#pragma once

#include <algorithm>
#include <cstddef>
#include <vector>

#include "roughness/field.hpp"

namespace mcmd::rough {

// Blocks of kBlock² cells aligned to global raster coordinates, so every
// window of a tiled fill cuts the same blocks: the unit of local statistics
// and of where noise is generated at all.
constexpr int kBlock = 32;

// Cells [x0, x1) × [y0, y1) of a field (empty: x1 <= x0 or y1 <= y0).
struct Rect {
  int x0, x1, y0, y1;
  bool empty() const { return x1 <= x0 || y1 <= y0; }
};

struct Blocks {
  int nx = 0, ny = 0;    // blocks per row, per column
  int ox = 0, oy = 0;    // local x + ox = position in the block lattice (cells); likewise y
  std::vector<Rect> noise_box;  // per block, the box of its noise cells: noise is generated where not empty
  std::size_t index(int i, int j) const { return static_cast<std::size_t>(j) * nx + i; }
  bool active(int i, int j) const { return !noise_box[index(i, j)].empty(); }
  bool inside(int i, int j) const { return i >= 0 && j >= 0 && i < nx && j < ny; }
  // Local cells [x0, x1) of block column i (rows likewise), clipped to the field.
  int x0(int i) const { return std::max(0, i * kBlock - ox); }
  int x1(int i, int w) const { return std::min(w, (i + 1) * kBlock - ox); }
  int y0(int j) const { return std::max(0, j * kBlock - oy); }
  int y1(int j, int h) const { return std::min(h, (j + 1) * kBlock - oy); }
};

inline int positive_mod(long long v, int m) { return static_cast<int>(((v % m) + m) % m); }


// The part of a field whose cells may carry noise: every per-cell array of
// the noise (targets, noise cells, values) covers it, not the whole field (a
// void's field is its void grown by a margin of up to 32 + its extent on each
// side). Field coordinates; row-major, w wide.
struct Area {
  int x0 = 0, y0 = 0, w = 0, h = 0;
  std::size_t cells() const { return static_cast<std::size_t>(w) * static_cast<std::size_t>(h); }
  std::size_t index(int x, int y) const {
    return static_cast<std::size_t>(y - y0) * static_cast<std::size_t>(w) + static_cast<std::size_t>(x - x0);
  }
};

// The block lattice of a field, no block active.
inline Blocks block_lattice(const RoughField& g) {
  Blocks b;
  b.ox = positive_mod(g.x0, kBlock);
  b.oy = positive_mod(g.y0, kBlock);
  b.nx = (g.w + kBlock - 1) / kBlock + 1;
  b.ny = (g.h + kBlock - 1) / kBlock + 1;
  b.noise_box.assign(static_cast<std::size_t>(b.nx) * b.ny, Rect{0, 0, 0, 0});
  return b;
}

}  // namespace mcmd::rough
