// The discrete thin-plate energy on a lattice and its Gauss-Seidel smoother.
//
//   E(z) = Σ z_xx² + Σ z_yy² + 2 Σ z_xy²
//
// z_xx = z(x-1,y) - 2 z(x,y) + z(x+1,y) for every centre whose 3 cells lie in
// the lattice (z_yy likewise), z_xy = the cross difference of every 2×2 block.
// Only terms that fit inside the lattice are summed: the natural boundary
// condition of a free plate. In the interior ∂E/∂z is the 13-point biharmonic
// stencil; at the border it stays the gradient of a positive semi-definite
// energy whose null space is the planes, so Gauss-Seidel (exact minimisation
// along one cell) converges. (Σ (5-point Laplacian)² over interior centres has
// the same interior stencil but every discrete harmonic function in its null
// space: a void at the border then becomes an ill-posed Cauchy problem.)
#pragma once

#include "thin_plate/lattice.hpp"

namespace mcmd {

// (A z)_p = ½ ∂E/∂z_p at cell (x, y) and the diagonal A_pp (0 when no term
// touches the cell, e.g. the corners of a 2×2 lattice have only z_xy).
struct ThinPlateRow {
  double az = 0.0;
  double diag = 0.0;
};
// With tension t > 0 the membrane term t·Σ_edges (z_i - z_j)² joins E: in the
// interior (A z)_p gains t·(4 z_p - Σ 4 neighbours), at the border only the
// edges inside the lattice count.
// z is a w×h row-major lattice.
ThinPlateRow thin_plate_row(const double* z, int w, int h, int x, int y, double tension = 0.0);

// `sweeps` lexicographic SOR sweeps of A z = rhs over the free cells (rhs may
// be null for 0), factor `omega` (1 = Gauss-Seidel). Pinned cells never change.
// Banded lattices (lattice.hpp) run on `threads` threads, same result for any count.
void relax(Lattice& lat, const double* rhs, int sweeps, double omega = 1.0, int threads = 1);

// rhs - A z at one cell (rhs may be null); with springs, A includes the soft
// data term: (A z)_p += spring_p (z_p - target_p).
double residual_at(const Lattice& lat, const double* rhs, int x, int y);

// rhs - A z at the cells of one run of free cells, into out[0 .. x1 - x0).
void residual_run(const Lattice& lat, const double* rhs, const Span& sp, double* out);

// r = rhs - A z at the free cells; entries of pinned cells are left as they
// are (keep them 0). Pre: r.size() == z.size().
void residual(const Lattice& lat, const double* rhs, std::vector<double>& r, int threads = 1);

}  // namespace mcmd
