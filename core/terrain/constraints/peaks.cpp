#include "mcmd/peaks.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "mcmd/terrain.hpp"
#include "roughness/noise.hpp"

namespace mcmd {

namespace {

constexpr double kDomain = 100.0;
constexpr std::uint64_t kPeakStream = 31, kGaussStream = 32;

double value_of(const Peak& p, double x, double y) {
  const double q = p.B * (x - p.alpha) * (x - p.alpha) + p.C * (y - p.beta) * (y - p.beta) + p.D;
  return p.exponential ? p.A * std::exp(-q) : p.A / q;
}

void check(int w, int h, const PeaksParams& params) {
  check_terrain_size(w, h);
  if (params.peaks.empty()) throw std::invalid_argument("a peaks surface needs at least one peak");
  for (const Peak& p : params.peaks) {
    const double v[] = {p.A, p.B, p.C, p.D, p.alpha, p.beta};
    for (double x : v)
      if (!std::isfinite(x)) throw std::invalid_argument("peak parameters must be finite numbers");
    if (p.B < 0 || p.C < 0 || (!p.exponential && p.D <= 0))
      throw std::invalid_argument("peaks need B, C >= 0 and, for a rational peak, D > 0");
  }
  if (!std::isfinite(params.E)) throw std::invalid_argument("the peaks' noise E must be a finite number");
}

}  // namespace

std::vector<Peak> iizuka_table1() {
  return {{3000, 2, 6, 90, 20, 90, false},   {4000, 2, 4, 80, 70, 80, false}, {4000, 4, 2, 50, 40, 80, false},
          {4000, 4, 2, 120, 30, 20, false},  {100, 0.05, 0.05, 0, 20, 50, true}, {50, 0.02, 0.02, 0, 80, 30, true}};
}

std::vector<Peak> random_peaks(int count, std::uint64_t seed) {
  const UniformHash draw(seed, kPeakStream);
  std::vector<Peak> out;
  for (int k = 0; k < count; ++k) {
    const auto u = [&](int j) { return 0.5 * (draw(k, j) + 1.0); };
    const bool e = k % 2 == 1;
    Peak p;
    p.exponential = e;
    p.A = e ? 50 + 50 * u(0) : 3000 + 1000 * u(0);
    p.B = e ? 0.02 + 0.03 * u(1) : 2 + 4 * u(1);
    p.C = e ? 0.02 + 0.03 * u(2) : 2 + 4 * u(2);
    p.D = e ? 0.0 : 50 + 70 * u(3);
    p.alpha = 10 + 80 * u(4);
    p.beta = 10 + 80 * u(5);
    out.push_back(p);
  }
  return out;
}

std::vector<double> peaks_surface(int w, int h, const PeaksParams& params) {
  check(w, h, params);
  std::vector<double> z(static_cast<std::size_t>(w) * h);
  double top = 0.0;
  for (int r = 0; r < h; ++r)
    for (int c = 0; c < w; ++c) {
      const double x = w > 1 ? kDomain * c / (w - 1) : kDomain / 2;
      const double y = h > 1 ? kDomain * (1.0 - static_cast<double>(r) / (h - 1)) : kDomain / 2;
      double v = 0.0;
      for (const Peak& p : params.peaks) v += value_of(p, x, y);
      top = std::max(top, v);
      z[static_cast<std::size_t>(r) * w + c] = v;
    }
  const bool scaled = params.z_high > params.z_low && top > 0;
  for (int r = 0; r < h; ++r)
    for (int c = 0; c < w; ++c) {
      double& v = z[static_cast<std::size_t>(r) * w + c];
      if (params.E != 0) v += params.E * hash_normal(params.seed ^ kGaussStream, c, r);
      if (v < params.threshold) v = 0.0;
      if (scaled) v = params.z_low + (params.z_high - params.z_low) * v / top;
    }
  return z;
}

}  // namespace mcmd
