// Coarse-to-fine interpolation between two nested lattices (side mc -> 2mc-1):
// cells shared with the coarse lattice are copied, new cells come from the
// 4-point interpolatory cubic (-1/16, 9/16, 9/16, -1/16) along rows and
// columns (tensor product for square centres). Where the 4th point would fall
// outside, the 3-point quadratic (3/8, 3/4, -1/8) is used, and the 2-point
// mean on a 2-cell coarse side. Exact on cubics (quadratics at the border).
#pragma once

#include <array>
#include <cstddef>

namespace mcmd {

// The 1D rule: fine index x takes coarse indices first .. first+count-1.
struct Weights1D {
  int first = 0;
  int count = 0;
  double w[4] = {0, 0, 0, 0};
};
Weights1D cubic_weights_1d(int x, int mc);

struct ProlongWeights {
  std::array<std::size_t, 16> index{};  // coarse cells
  std::array<double, 16> weight{};
  int count = 0;
};

// The coarse cells and weights that make fine cell (x, y). Pre: mc >= 2,
// 0 <= x, y < 2mc-1.
ProlongWeights prolong_weights(int x, int y, int mc);

// Σ weight · coarse[index] for fine cell (x, y).
double prolong_at(const double* coarse, int mc, int x, int y);

}  // namespace mcmd
