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
Weights1D cubic_weights_1d(int x, int mc);

// The interpolated value at fine cell (x, y) from a coarse lattice of mw×mh
// cells (row-major). Pre: mw, mh >= 2, 0 <= x <= 2mw-2, 0 <= y <= 2mh-2.
double prolong_at(const double* coarse, int mw, int mh, int x, int y);

}  // namespace mcmd
