// -rs auto's amplitude (internal to roughness/): the scale per block that
// gives the noise the terrain's Laplacian variance around it.
#pragma once

#include <vector>

#include "roughness/blocks.hpp"
#include "roughness/statistics.hpp"

namespace mcmd::rough {

// -rs auto: the noise's scale per block (every block of the lattice: the
// amplitude is interpolated between block centres). Each block gets the
// Laplacian variance of the terrain around it (directional semivariogram of
// the constraint pairs in the smallest square of blocks with kMinPairs pairs
// per lag), and the scale that gives that variance to a noise whose own is
// `noise_laplacian` (noise_laplacian_variance: known from the octaves, not
// measured). Where the pairs are too few within kMaxRadius blocks (scattered
// samples, the middle of huge voids), the target blends into the global one.
std::vector<double> block_scales(const Blocks& blocks, const LagTable& lags, const RoughnessModel& global,
                                 double noise_laplacian);

}  // namespace mcmd::rough
