// A structure-following term for scattered samples: the energy gains
// Σ k · z_uu², where u is, around each cell, the direction along which the
// current fill curves least (along a valley or a ridge) and k grows with how
// clearly it has one. Between samples a thin plate rounds a valley into a
// chain of bowls; this term makes the valley carry on along its own
// direction (docs/default-method.md, Structure term).
//
// The direction comes from the fill's Hessian H, measured at a spacing of 2
// cells: H² summed over 4×4 blocks of cells and smoothed over the blocks is a
// tensor whose major eigenvector is the direction of most curvature; u is the
// minor one, and its coherence (λ1 − λ2)/(λ1 + λ2) in [0, 1] scales k. The
// coefficients are per block, so the term costs a field-sized work array
// and two passes per application.
#pragma once

#include <vector>

#include "thin_plate/lattice.hpp"

namespace mcmd {

class StructureTerm {
 public:
  // The term for the current values of `lat`: k = (strength − 1) · coherence,
  // so a perfectly one-directional block curves `strength` times as stiffly
  // along u as across it. strength <= 1 gives an empty term.
  StructureTerm(const Lattice& lat, double strength, int threads);

  bool empty() const { return coef_.empty(); }

  // out −= K v at the free cells of `lat` (K = ½ ∂²E/∂z², symmetric and
  // positive semi-definite): Multigrid::solve_pcg's extra operator, with
  // `out` holding −A v. Pre: v and out are lat-sized; `lat` is the lattice
  // given to the constructor (same size and free cells).
  void subtract(const Lattice& lat, const std::vector<double>& v, std::vector<double>& out, int threads) const;

 private:
  // Per block: √k times the weights of z_xx, z_yy and the cross difference
  // (4 z_xy) in z_uu.
  struct Weights {
    double xx = 0.0, yy = 0.0, xy = 0.0;
  };
  const Weights* row_of(int y) const { return coef_.data() + static_cast<std::size_t>(y / kBlock) * blocks_w_; }
  const Weights& at(int x, int y) const { return row_of(y)[x / kBlock]; }
  // What subtract takes from a cell on the lattice's edge rows or columns.
  double transposed_at_edge(int x, int y) const;

  static constexpr int kBlock = 4;
  int w_ = 0, h_ = 0, blocks_w_ = 0;
  std::vector<Weights> coef_;
  mutable std::vector<double> g_;  // √k z_uu per cell, the work array of subtract
};

}  // namespace mcmd
