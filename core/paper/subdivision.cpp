#include "paper/subdivision.hpp"

#include <bit>

namespace mcmd {

int level_of(int x, int y, int n) {
  const int h = half_spacing_of(x, y, n);
  if (h == (1 << n)) return -1;
  return n - 1 - std::countr_zero(static_cast<unsigned>(h));
}

namespace {

void push_if_inside(Parents& p, int x, int y, int side) {
  if (x >= 0 && y >= 0 && x < side && y < side) p.cell[p.count++] = {x, y};
}

}  // namespace

Parents parents_of(Scheme scheme, int x, int y, int n) {
  Parents p;
  const int h = half_spacing_of(x, y, n);
  if (h == (1 << n)) return p;  // a corner: a root of the hierarchy
  const int side = (1 << n) + 1;
  if (is_square_centre(x, y, h)) {
    push_if_inside(p, x - h, y - h, side);
    push_if_inside(p, x + h, y + h, side);
    if (scheme == Scheme::diamond_square) {
      push_if_inside(p, x + h, y - h, side);
      push_if_inside(p, x - h, y + h, side);
    }
    return p;
  }
  // Edge midpoint: the edge runs along x when x/h is odd, along y otherwise.
  const bool along_x = (x / h) & 1;
  const int ex = along_x ? h : 0;
  const int ey = along_x ? 0 : h;
  push_if_inside(p, x - ex, y - ey, side);
  push_if_inside(p, x + ex, y + ey, side);
  if (scheme == Scheme::diamond_square) {  // the square centres on either side
    push_if_inside(p, x - ey, y - ex, side);
    push_if_inside(p, x + ey, y + ex, side);
  }
  return p;
}

}  // namespace mcmd
