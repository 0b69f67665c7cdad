// Iizuka's closed-form multi-peak terrains (Iizuka 1990, seed 004, eq. 8):
//   Z(x, y) = Σ A / (B (x−α)² + C (y−β)² + D)          (rational peaks)
//           + Σ A · exp(−(B (x−α)² + C (y−β)² + D))      (exponential peaks)
//           + E · GAUSS
// over the domain 0 <= x, y <= 100 stretched over the raster (y up, as in
// the paper's maps); values below the threshold Z_sh become 0.
#pragma once

#include <cstdint>
#include <limits>
#include <vector>

namespace mcmd {

struct Peak {
  double A = 0, B = 0, C = 0, D = 0;
  double alpha = 50, beta = 50;  // position in the 0..100 domain
  bool exponential = false;
};

struct PeaksParams {
  std::vector<Peak> peaks;
  double E = 0.0;          // amplitude of the Gaussian noise added per cell
  double threshold = -std::numeric_limits<double>::infinity();  // Z_sh
  // When z_high > z_low, Z is mapped linearly so that 0 -> z_low and the
  // highest value of the noise-free surface -> z_high.
  double z_low = 0.0, z_high = 0.0;
  std::uint64_t seed = 0;
};

// Table 1 of the paper: four rational peaks and two exponential ones (E = 0
// gives its Fig. 4, E = -5 its Fig. 5; both with Z_sh = 10).
std::vector<Peak> iizuka_table1();

// `count` peaks drawn in the ranges of Table 1 (alternately rational and
// exponential), positions in [10, 90]; a pure function of its arguments.
std::vector<Peak> random_peaks(int count, std::uint64_t seed);

// Z at every cell of a w×h raster, row-major. Throws std::invalid_argument
// for a bad size, no peak, or a rational peak that can divide by 0 (D <= 0).
std::vector<double> peaks_surface(int w, int h, const PeaksParams& params);

}  // namespace mcmd
