// Coarse-to-fine interpolation between two nested lattices (mc cells along an
// axis -> up to 2mc-1):
// cells shared with the coarse lattice are copied, new cells come from the
// 4-point interpolatory cubic (-1/16, 9/16, 9/16, -1/16) along rows and
// columns (tensor product for square centres). Where the 4th point would fall
// outside, the 3-point quadratic (3/8, 3/4, -1/8) is used, and the 2-point
// mean on a 2-cell coarse side. Exact on cubics (quadratics at the border).
#pragma once

#include <cstddef>

namespace mcmd {

// The 1D rule: fine index x takes coarse indices first .. first+count-1.
struct Weights1D {
  int first = 0;
  int count = 0;
  double w[4] = {0, 0, 0, 0};
};
// Inline: the multigrid transfers call it for every cell.
inline Weights1D cubic_weights_1d(int x, int mc) {
  Weights1D r;
  if ((x & 1) == 0) {
    r.first = x / 2;
    r.count = 1;
    r.w[0] = 1.0;
    return r;
  }
  const int a = (x - 1) / 2;  // left coarse neighbour
  const bool left = a - 1 >= 0;
  const bool right = a + 2 <= mc - 1;
  if (left && right) {
    r = {a - 1, 4, {-1.0 / 16, 9.0 / 16, 9.0 / 16, -1.0 / 16}};
  } else if (left) {
    r = {a - 1, 3, {-1.0 / 8, 3.0 / 4, 3.0 / 8, 0.0}};
  } else if (right) {
    r = {a, 3, {3.0 / 8, 3.0 / 4, -1.0 / 8, 0.0}};
  } else {
    r = {a, 2, {0.5, 0.5, 0.0, 0.0}};
  }
  return r;
}


// The interpolated value at fine cell (x, y) from a coarse lattice of mw×mh
// cells (row-major). Pre: mw, mh >= 2, 0 <= x <= 2mw-2, 0 <= y <= 2mh-2.
double prolong_at(const double* coarse, int mw, int mh, int x, int y);

// prolong_at for the fine cells [x0, x1) of row y, into out[0 .. x1 - x0):
// the same sums, with the row's weights found once.
void prolong_run(const double* coarse, int mw, int mh, int y, int x0, int x1, double* out);

}  // namespace mcmd
