// Subdivision schemes (Miller 1986) on a 2^n + 1 grid, as pure functions of a
// cell's coordinates: the hierarchy is never stored (paper §2).
//
// Level r has half-spacing h = 2^(n-1-r), r = 0 .. n-1. A cell's level follows
// from the lowest set bit of (x | y): h = lowbit(x | y). The four grid corners
// belong to no level (level -1): they are the roots and have no parents.
//
// Diamond-square, level r, two passes:
//   square step  (x/h, y/h both odd)    diamond step (exactly one odd)
//       A . B                                  C
//       . x .     parents A B C D              . 
//       C . D     (the 4 square corners)   A . x . B   parents: the edge's 2 ends
//                                              .       and the 2 square centres
//                                              D       beside it (3 at a border)
// Triangle-edge, level r, one pass: every new cell is the midpoint of one
// edge of a triangle, parents are that edge's two ends. Squares are cut along
// their NW-SE diagonal (top-left to bottom-right in raster order):
//   A . .          edge midpoints: parents are the 2 ends of the edge;
//   . x .          square centres: parents are A and D, the NW-SE diagonal.
//   . . D
#pragma once

#include <array>
#include <cstdint>

namespace mcmd {

// butterfly: triangle-edge's hierarchy (its parents, its MDBU) with the
// butterfly stencil top-down (butterfly.hpp).
enum class Scheme { diamond_square, triangle_edge, butterfly };

struct CellXY {
  int x = 0;
  int y = 0;
};

struct Parents {
  std::array<CellXY, 4> cell{};
  int count = 0;
};

// Lowest set bit of (x | y) for a non-corner cell; 0 marks a corner-like
// cell of the whole grid (x | y == 0 or multiples of 2^n).
inline int half_spacing_of(int x, int y, int n) {
  const unsigned v = static_cast<unsigned>(x | y) | (1u << n);
  return static_cast<int>(v & (~v + 1u));
}

// Level r of a cell (0 = the grid centre's level), or -1 for the four corners.
int level_of(int x, int y, int n);

// Half-spacing of level r: 2^(n-1-r).
inline int half_spacing(int level, int n) { return 1 << (n - 1 - level); }

// True for a square-step cell (centre of a 2h square), false for an edge midpoint.
inline bool is_square_centre(int x, int y, int h) { return ((x / h) & 1) && ((y / h) & 1); }

// Parents (ascendants) of cell (x, y) under `scheme` on a grid of side 2^n+1.
// Pre: (x, y) inside the grid. Post: count == 0 for corners; parents lie inside
// the grid and belong to a coarser level, or (diamond-square edge midpoints)
// to the square-step pass of the same level.
Parents parents_of(Scheme scheme, int x, int y, int n);

}  // namespace mcmd
