#include "terrain/erosion/stream_power.hpp"

#include <algorithm>
#include <cmath>

#include "common/d8.hpp"

namespace mcmd::terrain {

namespace {

// A^m for an area of `cells` grid cells.
double area_term(double cells, const StreamPower& sp) {
  const double a = cells * sp.spacing * sp.spacing;
  return sp.m == 0.5 ? std::sqrt(a) : std::pow(a, sp.m);
}

// The new height x of a cell at `b` (its height plus uplift) above a
// receiver at `zr`, `length` away: x − b + c·((x − zr)/length)^n = 0 with
// c = K·dt·A^m, x in [zr, b]. n = 1 is closed form; otherwise Newton from b
// (the function is convex and increasing there: it converges from above).
double implicit_height(double b, double zr, double c, double length, double n) {
  if (b <= zr) return b;
  if (n == 1.0) {
    const double f = c / length;
    return (b + f * zr) / (1.0 + f);
  }
  double x = b;
  for (int it = 0; it < 40; ++it) {
    const double s = (x - zr) / length;
    const double g = x - b + c * std::pow(s, n);
    const double dg = 1.0 + c * n * std::pow(s, n - 1.0) / length;
    const double next = std::max(zr, x - g / dg);
    if (std::fabs(next - x) <= 1e-12 * (1.0 + std::fabs(x))) return next;
    x = next;
  }
  return x;
}

}  // namespace

void stream_power_step(std::vector<double>& z, const std::vector<double>& uplift, double rate,
                       const std::vector<std::uint8_t>& fixed, const Drainage& d, const StreamPower& sp, double dt) {
  // From the outlets up, each free cell's uplift, then its implicit height
  // above its receiver (already at its new height).
  const double k = sp.K * dt, lift = rate * dt;
  for (const std::int32_t i : d.order) {
    if (fixed[i]) continue;
    z[i] += uplift[i] * lift;
    const std::uint8_t to = d.to[i];
    if (to == kOutlet) continue;
    const double c = k * area_term(d.area[i], sp);
    z[i] = implicit_height(z[i], z[i + d.offset[to]], c, d8::length(to) * sp.spacing, sp.n);
  }
}

double steady_state_erodibility(const std::vector<double>& target, const std::vector<double>& uplift,
                                const std::vector<std::uint8_t>& fixed, const Drainage& d, const StreamPower& sp) {
  // With K = 1 each free cell stands (U / A^m)^(1/n) · length above its
  // receiver; every such height scales as K^(-1/n). A high quantile is the
  // relief of the mountains, which the mean (set by the broad valleys)
  // would let grow.
  const std::size_t n = target.size();
  std::vector<double> rise(n, 0.0), anchor(n, 0.0), steady, wanted;
  steady.reserve(n), wanted.reserve(n);
  for (const std::int32_t i : d.order) {
    const std::int32_t r = d.receiver(i);
    if (fixed[i] || r < 0) {
      anchor[i] = target[i];
      continue;
    }
    const double length = d8::length(d.to[i]) * sp.spacing;
    rise[i] = rise[r] + std::pow(uplift[i] / area_term(d.area[i], sp), 1.0 / sp.n) * length;
    anchor[i] = anchor[r];
    steady.push_back(rise[i]);
    wanted.push_back(target[i] - anchor[i]);
  }
  if (steady.empty()) return 0.0;
  const auto quantile = [](std::vector<double>& v) {
    const auto k = v.begin() + static_cast<std::ptrdiff_t>(0.99 * static_cast<double>(v.size() - 1));
    std::nth_element(v.begin(), k, v.end());
    return *k;
  };
  const double s = quantile(steady), t = quantile(wanted);
  if (!(t > 0.0) || !(s > 0.0)) return 0.0;
  return std::pow(s / t, sp.n);
}

}  // namespace mcmd::terrain
