#include "mcmd/noise.hpp"

#include <cmath>
#include <numbers>

namespace mcmd {

namespace {

// SplitMix64 finaliser: a strong 64-bit mixer, so neighbouring coordinates
// give unrelated values.
std::uint64_t mix(std::uint64_t v) {
  v += 0x9E3779B97F4A7C15ull;
  v = (v ^ (v >> 30)) * 0xBF58476D1CE4E5B9ull;
  v = (v ^ (v >> 27)) * 0x94D049BB133111EBull;
  return v ^ (v >> 31);
}

std::uint64_t hash3(std::uint64_t seed, std::int64_t gx, std::int64_t gy, std::uint64_t stream) {
  std::uint64_t h = mix(seed ^ (stream * 0xD6E8FEB86659FD93ull));
  h = mix(h ^ static_cast<std::uint64_t>(gx));
  return mix(h ^ static_cast<std::uint64_t>(gy));
}

// Uniform in [0, 1) from the top 53 bits.
double unit(std::uint64_t h) { return static_cast<double>(h >> 11) * 0x1.0p-53; }

}  // namespace

double hash_uniform(std::uint64_t seed, std::int64_t gx, std::int64_t gy) {
  return 2.0 * unit(hash3(seed, gx, gy, 1)) - 1.0;
}

double hash_normal(std::uint64_t seed, std::int64_t gx, std::int64_t gy) {
  // Box-Muller on two independent streams of the same key.
  const double u1 = 1.0 - unit(hash3(seed, gx, gy, 2));  // (0, 1]
  const double u2 = unit(hash3(seed, gx, gy, 3));
  return std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * std::numbers::pi * u2);
}

double paper_delta(std::uint64_t seed, std::int64_t gx, std::int64_t gy, int level, int dim,
                   double H, double rt, double rs) {
  return (hash_uniform(seed, gx, gy) + rt) * rs * std::exp2(-level * dim * H);
}

}  // namespace mcmd
