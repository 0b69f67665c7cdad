// The paper's distance-shaped interpolation weight Δ (eq. 3, the consistent
// form of eq. 2):  Δ(e, d) = e · w(d),
//   w(d) = 1 − σ(I) · (1 − (1 − d/dmax)^|I|),  σ(I) = +1 if I >= 0 else −1.
// I = 0 gives w = 1 (plain mean); I > 0 gives bell-like, I < 0 ridged shapes.
#pragma once

#include <span>

#include "mcmd/params.hpp"

namespace mcmd {

// w(d). Pre: dmax > 0, 0 <= d <= dmax. Post: w > 0 for d < dmax.
double delta_weight(double I, double d, double dmax);

// One parent/child contribution to a weighted average.
struct Contribution {
  double e;  // elevation
  double d;  // euclidean distance parent-child, in cells
  double I;  // shape parameter of the contributing cell's state
};

// Combine contributions with Δ in `form`. Pre: contributions not empty.
double combine(DeltaForm form, std::span<const Contribution> contributions, double dmax);

// combine() with the weights given, w[k] = delta_weight(I_k, d_k, dmax) (a
// caller that meets few distances computes them once): the same arithmetic,
// the same bits. Pre: n >= 1.
double combine_weighted(DeltaForm form, const double* e, const double* w, int n);

}  // namespace mcmd
