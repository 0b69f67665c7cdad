#include "terrain/skeleton/fbm_path.hpp"

#include <cmath>

#include "roughness/noise.hpp"

namespace mcmd::terrain {

std::vector<double> fbm_path(int steps, double H, double sigma, std::uint64_t seed, std::uint64_t stream) {
  int n = 1;
  while (n < steps) n *= 2;
  std::vector<double> v(static_cast<std::size_t>(n) + 1, 0.0);
  const std::uint64_t key = seed ^ (stream * 0x9E3779B97F4A7C15ull);
  v[n] = sigma * hash_normal(key, n, 0);
  // A midpoint's displacement keeps Var[v(t+s) − v(t)] ∝ s^(2H) at every scale.
  const double shrink = std::sqrt(std::max(0.0, 1.0 - std::exp2(2.0 * H - 2.0)));
  for (int half = n / 2; half >= 1; half /= 2) {
    const double scale = sigma * std::pow(2.0 * half / n, H) * shrink;
    for (int i = half; i < n; i += 2 * half)
      v[i] = 0.5 * (v[i - half] + v[i + half]) + scale * hash_normal(key, i, half);
  }
  v.resize(static_cast<std::size_t>(steps) + 1);
  return v;
}

}  // namespace mcmd::terrain
