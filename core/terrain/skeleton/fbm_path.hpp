// One-dimensional fractional Brownian motion by random midpoint displacement
// (Fournier et al. 1982): the side impacts of a ridge particle's heading.
#pragma once

#include <cstdint>
#include <vector>

namespace mcmd::terrain {

// Samples 0 .. steps of an fBm starting at 0 whose increment over the whole
// length has standard deviation `sigma`; Hurst exponent H in [0, 1]. A pure
// function of (seed, stream) and the arguments.
std::vector<double> fbm_path(int steps, double H, double sigma, std::uint64_t seed, std::uint64_t stream);

}  // namespace mcmd::terrain
