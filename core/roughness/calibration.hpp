// -rs auto's amplitude (internal to roughness/): the noise's Laplacian
// moments per block and the scale per block that gives the noise the
// terrain's Laplacian variance around it.
#pragma once

#include <cstdint>
#include <vector>

#include "roughness/blocks.hpp"
#include "roughness/statistics.hpp"

namespace mcmd::rough {

// The noise's second differences over the target cells of one block: the
// moments of its 5-point Laplacian, and Σ(dxx² + dyy²).
struct NoiseMoments {
  double n = 0, q = 0, qq = 0, curvature = 0;
  void add(const NoiseMoments& o) { n += o.n; q += o.q; qq += o.qq; curvature += o.curvature; }
  double laplacian_var() const { return n > 1 ? std::max(0.0, qq / n - (q / n) * (q / n)) : 0.0; }
};

// Per active block (target cells lie in active blocks only, inside area `a`
// with a cell to spare around them), block rows on `threads` threads; each
// row segment a pass that vectorises.
std::vector<NoiseMoments> noise_moments(const RoughField& g, const Area& a, const std::vector<std::uint8_t>& target,
                                        const Blocks& b, const std::vector<double>& noise, int threads);

// -rs auto: the noise's scale per block. Each block with target cells gets the
// Laplacian variance of the terrain around it (directional semivariogram of
// the constraint pairs in the smallest square of blocks with kMinPairs pairs
// per lag) and the scale that gives the noise that variance over the target
// cells of the block and its 8 neighbours. Where the pairs are too few within
// kMaxRadius blocks (scattered samples, the middle of huge voids), the target
// blends into the global one. Blocks without target cells take the mean of
// their neighbours with one (they only support the interpolation).
std::vector<double> block_scales(const Blocks& blocks, const LagTable& lags, const std::vector<NoiseMoments>& lap,
                                 const RoughnessModel& global, double global_scale);

// noise (over area `a`) × the block scales interpolated bilinearly between
// block centres (a smooth amplitude field), in place; the noise lies in the
// active blocks' noise boxes only.
void scale_noise(const Area& a, const Blocks& blocks, const std::vector<double>& scales, std::vector<double>& noise,
                 int threads);

}  // namespace mcmd::rough
