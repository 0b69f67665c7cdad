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
  double curvature = 0.0; // variance of a second difference, 8γ(1) - 2γ(2)
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
// rs_auto: H and amplitude from estimate_roughness (the second-difference
// variance of the noise is 0.85² of the terrain's); else rs > 0: amplitude
// rs · noise_unit for the coarsest octave, H = params.H. No-op otherwise.
void add_roughness(Grid& grid, const FillParams& params);

}  // namespace mcmd
