#include "roughness/calibration.hpp"

#include <cmath>

namespace mcmd::rough {

namespace {

// Laplacian variance ÷ twice the second-difference variance on the benchmark
// DEMs (dense data): 1.37-1.47, median 1.39 (dxx and dyy correlate).
constexpr double kLapPerCurvature = 1.39;

}  // namespace

std::vector<double> block_scales(const Blocks& blocks, const LagTable& lags, const RoughnessModel& global,
                                 double noise_laplacian) {
  const double global_target = kLapPerCurvature * 2.0 * global.curvature;
  std::vector<double> scale(static_cast<std::size_t>(blocks.nx) * blocks.ny);
  for (int bj = 0; bj < blocks.ny; ++bj)
    for (int bi = 0; bi < blocks.nx; ++bi) {
      LagSums around;
      for (int r = 1; r <= kMaxRadius; ++r) {
        around = lags.box(bi - r, bj - r, bi + r, bj + r);
        if (around.min_laplacian_count() >= kMinPairs) break;
      }
      const double local = around.laplacian_variance();
      const double trust =
          local > 0 ? smoothstep((around.min_laplacian_count() - 0.25 * kMinPairs) / (0.75 * kMinPairs)) : 0.0;
      const double target = trust * local + (1.0 - trust) * global_target;
      scale[blocks.index(bi, bj)] = std::sqrt(target / noise_laplacian);
    }
  return scale;
}

}  // namespace mcmd::rough
