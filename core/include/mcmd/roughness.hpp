// Natural roughness for the default method: a fractal correction added to the
// smooth thin-plate fill, zero at the constraint cells and growing smoothly
// into the voids (a conditional simulation with the thin plate as the
// interpolator).
#pragma once

#include <cstdint>
#include <vector>

#include "mcmd/fill.hpp"

namespace mcmd {

// Terrain statistics from the constraint cells: semivariogram γ(d) over
// horizontal and vertical pairs of constraint cells at lags 1, 2, 4, 8, 16.
struct RoughnessModel {
  double H = 0.5;         // Hurst exponent, from the slope of log γ against log d
  double curvature = 0.0; // variance of a second difference: 8γ(1) - 2γ(2) from many lag-1
                          // pairs, a calibrated fBm form γ(1)(8 - 2·4^H) from few (scattered samples)
  bool valid = false;     // enough pairs to estimate
};
RoughnessModel estimate_roughness(const Grid& grid);

// Unconditioned fractal noise at every cell: octaves of spacing 2^j
// (j = 0 .. octaves-1), each white noise on a lattice rotated by j golden
// angles and interpolated with Catmull-Rom splines (smooth, no axis-aligned
// blocks), weighted 2^(jH). Keyed on (seed, global coordinates): any window of
// a raster sees the same noise.
std::vector<double> fractal_noise(const Grid& grid, std::uint64_t seed, double H, int octaves);

// Add roughness to the unknown cells of `grid`, which hold the smooth fill.
// The noise is generated only in 32² blocks (aligned to global coordinates)
// near voids and conditioned on the constraints. rs_auto: H from
// estimate_roughness; the amplitude per block makes the 5-point Laplacian
// variance of fill + noise over the block's voids (and its neighbours') equal
// to the terrain's around it (directional semivariogram of the nearest
// constraint pairs, through a summed-area table), blending into a global
// target from estimate_roughness's curvature where too few pairs lie within
// 4 blocks. Else rs > 0: amplitude
// rs · noise_unit for the coarsest octave, H = params.H. No-op otherwise.
void add_roughness(Grid& grid, const FillParams& params);

}  // namespace mcmd
