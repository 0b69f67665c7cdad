#include "roughness/amplitude.hpp"

#include <algorithm>
#include <cmath>

#include "roughness/simd.hpp"

namespace mcmd::rough {

AmplitudeRows::AmplitudeRows(const Amplitude& a, int x0, int x1)
    : a_(a),
      x0_(x0),
      x1_(x1),
      above_(static_cast<std::size_t>(std::max(0, x1 - x0)), a.constant),
      below_(above_) {}

void AmplitudeRows::centre_row(int cj, double* to) const {
  const Blocks& b = *a_.blocks;
  // A scale that is not finite (no terrain to measure) counts as 0.
  const auto at = [&](int bi) {
    const double s = a_.scales[b.index(std::clamp(bi, 0, b.nx - 1), std::clamp(cj, 0, b.ny - 1))];
    return std::isfinite(s) ? s : 0.0;
  };
  // In runs between two centres (ci, ci + 1): linear in tx.
  for (int x = x0_; x < x1_;) {
    const int ci = static_cast<int>(floor_of((x + b.ox + 0.5) / kBlock - 0.5));
    const int end = std::min(x1_, (ci + 1) * kBlock + kBlock / 2 - b.ox);  // the next centre
    const double left = at(ci), slope = at(ci + 1) - left;
    const double tx = (x + b.ox + 0.5) / kBlock - 0.5 - ci;  // then + k / kBlock: exact
    double* out = to + (x - x0_);
    for (int k = 0; k < end - x; ++k) out[k] = left + (tx + k * (1.0 / kBlock)) * slope;
    x = end;
  }
}

AmplitudeRows::Row AmplitudeRows::row(int y) {
  if (!a_.blocks) return Row{above_.data(), below_.data(), 0.0};
  const Blocks& b = *a_.blocks;
  const double fy = (y + b.oy + 0.5) / kBlock - 0.5;
  const int cj = static_cast<int>(floor_of(fy));
  if (cj != cj_) {
    cj_ = cj;
    centre_row(cj, above_.data());
    centre_row(cj + 1, below_.data());
  }
  return Row{above_.data(), below_.data(), fy - cj};
}

}  // namespace mcmd::rough
