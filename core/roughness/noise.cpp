#include "roughness/noise.hpp"

#include <cmath>
#include <numbers>

namespace mcmd {

double hash_uniform(std::uint64_t seed, std::int64_t gx, std::int64_t gy) { return UniformHash(seed)(gx, gy); }

double hash_normal(std::uint64_t seed, std::int64_t gx, std::int64_t gy) {
  // Box-Muller on two independent streams of the same key.
  const double u1 = 1.0 - noise_detail::unit(UniformHash(seed, 2).bits(gx, gy));  // (0, 1]
  const double u2 = noise_detail::unit(UniformHash(seed, 3).bits(gx, gy));
  return std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * std::numbers::pi * u2);
}

double paper_delta(std::uint64_t seed, std::int64_t gx, std::int64_t gy, int level, int dim,
                   double H, double rt, double rs) {
  return (hash_uniform(seed, gx, gy) + rt) * rs * std::exp2(-level * dim * H);
}

}  // namespace mcmd
