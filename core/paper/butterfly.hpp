// The butterfly stencil (Dyn, Levin & Gregory 1990; seed 002, Mandal, Qin &
// Vemuri) as a top-down scheme on the 2^n+1 grid. The triangulation is the
// triangle-edge one (squares cut along their NW-SE diagonal, subdivision.hpp),
// so the hierarchy and MDBU are triangle-edge's; only the interpolation of a
// new edge midpoint differs: instead of the mean of the edge's two ends, the
// eight points of the two triangles sharing the edge and of their neighbours:
//   1/2 (the two ends) + 2w (the two opposite vertices) − w (the four wings),
// w = 1/16, an affine combination exact on planes (interpolating, C1 limit).
#pragma once

#include "common/grid.hpp"

namespace mcmd {

constexpr double kButterflyW = 1.0 / 16.0;

// The butterfly value of edge midpoint (x, y) of half-spacing h from the
// grid's elevations at spacing 2h; false (out untouched) when a stencil point
// lies outside the grid (the caller then falls back to the edge's ends).
bool butterfly_value(const Grid& grid, int x, int y, int h, double& out);

}  // namespace mcmd
