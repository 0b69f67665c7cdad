#include "paper/delta.hpp"

#include <algorithm>
#include <cmath>

namespace mcmd {

double delta_weight(double I, double d, double dmax) {
  if (I == 0.0) return 1.0;
  const double t = std::clamp(1.0 - d / dmax, 0.0, 1.0);
  const double p = std::pow(t, std::fabs(I));
  return I > 0 ? p : 2.0 - p;  // 1 - σ(I)·(1 - p)
}

double combine(DeltaForm form, std::span<const Contribution> contributions, double dmax) {
  double sum = 0.0;
  double weights = 0.0;
  for (const Contribution& c : contributions) {
    const double w = delta_weight(c.I, c.d, dmax);
    sum += c.e * w;
    weights += w;
  }
  const double n = static_cast<double>(contributions.size());
  if (form == DeltaForm::paper) return sum / n;
  if (weights > 0.0) return sum / weights;
  // Every weight vanished (d == dmax with I > 0): fall back to the plain mean.
  double mean = 0.0;
  for (const Contribution& c : contributions) mean += c.e;
  return mean / n;
}

}  // namespace mcmd
