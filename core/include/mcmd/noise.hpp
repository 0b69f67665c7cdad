// Counter-based noise: a value is a pure hash of (seed, global x, global y), so
// it never depends on traversal order, threads or tiling (internal and external
// consistency, seed 003).
#pragma once

#include <cstdint>

namespace mcmd {

// Uniform in [-1, 1], a pure function of its arguments.
double hash_uniform(std::uint64_t seed, std::int64_t gx, std::int64_t gy);

// Standard normal deviate, a pure function of its arguments.
double hash_normal(std::uint64_t seed, std::int64_t gx, std::int64_t gy);

// MCMD's displacement δ (paper eq. 1) for a cell at level r in dimension `dim`:
//   δ = (u + rt) · rs · 2^(−r · dim · H),  u = hash_uniform(seed, gx, gy).
double paper_delta(std::uint64_t seed, std::int64_t gx, std::int64_t gy, int level, int dim,
                   double H, double rt, double rs);

}  // namespace mcmd
