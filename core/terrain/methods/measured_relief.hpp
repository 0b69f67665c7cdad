// rs auto for a terrain (the default method): the relief measured from the
// known cells of the canvas, a sketch's or a DEM's given to -upsample, so that
// the synthesised detail continues the given terrain's roughness to finer
// scales. Known cells only: ridge and river cells are lines, not terrain.
//   * the base lag b: the shortest distance at which enough pairs of known
//     cells lie on a row or a column (1 for a dense sketch, K for a DEM
//     supersampled by K);
//   * H: the slope of log γ against log d between d = b and 2b (the known
//     cells' semivariogram at the finest scales they have), halved, in [0, 1];
//   * the amplitude (the relief of fbm.hpp is linear in it):
//     - known cells on a lattice of spacing b > 1 (supersampling): the terrain
//       made is the thin plate through them plus the relief less its own thin
//       plate through the lattice (plate_terrain.hpp), so the relief must
//       carry what a thin plate through the lattice misses between its cells.
//       That is measured on the known cells themselves, one and two scales
//       up: R(2b), the mean squared residual of the thin plate through every
//       2nd lattice cell at the others, and R(4b) likewise. The relief's own
//       R₁(2b), R₁(4b) (amplitude 1, its cells on the same lattice, over a
//       corner of the raster) give the amplitude² R(2b)/R₁(2b) times
//       [R(2b)/R(4b)] / [R₁(2b)/R₁(4b)]: matched one scale up, with the
//       terrain's own shrink from scale to scale rather than the fractal's
//       (real DEMs grow smoother towards their finest scale: on four real
//       DEMs resampled and supersampled back, the made detail's semivariance
//       at lag 1 is 1.4–1.75× the real one's without it, 1.17–1.61× with it;
//       testdata's terrain 0.96×). The residual is
//       local too: averaged over the lattice cells around each, it gives the
//       relief a smooth factor per cell (`scale`, √(local/mean), bounded),
//       so rough slopes get more relief than flat valley floors;
//     - otherwise (voids to make next to dense known cells): the amplitude
//       that gives the relief the known cells' semivariance at lag b.
#pragma once

#include <cstdint>
#include <vector>

#include "mcmd/terrain.hpp"

namespace mcmd::terrain {

struct MeasuredRelief {
  double H = 0.7;
  double amplitude = 0.0;  // elevation units; 0 on a flat terrain
  int lag = 0;             // b
  bool lattice = false;    // the known cells lie on a lattice of spacing b > 1
  std::vector<double> scale;  // lattice: the relief's factor at each canvas cell; else empty
};

// Throws std::invalid_argument when fewer than 100 pairs of known cells lie
// at any lag up to 64 (nothing to measure: a skeleton, a few points).
// `fallback_H`: H when the lags b and 2b have too few pairs to fit it.
// `threads`: the relief's (the same bits for any count).
MeasuredRelief measure_relief(const Canvas& canvas, std::uint64_t seed, double fallback_H, int threads);

}  // namespace mcmd::terrain
