#include "paper/delta.hpp"

#include <algorithm>
#include <array>
#include <vector>
#include <cmath>

namespace mcmd {

double delta_weight(double I, double d, double dmax) {
  if (I == 0.0) return 1.0;
  const double t = std::clamp(1.0 - d / dmax, 0.0, 1.0);
  const double p = std::pow(t, std::fabs(I));
  return I > 0 ? p : 2.0 - p;  // 1 - σ(I)·(1 - p)
}

double combine(DeltaForm form, std::span<const Contribution> contributions, double dmax) {
  constexpr std::size_t kSmall = 8;  // a grid cell's parents; MDBU's children are rarely more
  std::array<double, 2 * kSmall> small;
  std::vector<double> large;
  const std::size_t n = contributions.size();
  double* e = small.data();
  if (n > kSmall) {
    large.resize(2 * n);
    e = large.data();
  }
  double* w = e + (n > kSmall ? n : kSmall);
  for (std::size_t k = 0; k < n; ++k) {
    e[k] = contributions[k].e;
    w[k] = delta_weight(contributions[k].I, contributions[k].d, dmax);
  }
  return combine_weighted(form, e, w, static_cast<int>(n));
}

double combine_weighted(DeltaForm form, const double* e, const double* w, int n) {
  double sum = 0.0;
  double weights = 0.0;
  for (int k = 0; k < n; ++k) {
    sum += e[k] * w[k];
    weights += w[k];
  }
  if (form == DeltaForm::paper) return sum / static_cast<double>(n);
  if (weights > 0.0) return sum / weights;
  // Every weight vanished (d == dmax with I > 0): fall back to the plain mean.
  double mean = 0.0;
  for (int k = 0; k < n; ++k) mean += e[k];
  return mean / static_cast<double>(n);
}

}  // namespace mcmd
