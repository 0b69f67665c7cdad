// Small deterministic terrains and void patterns shared by the core tests.
#pragma once

#include <cmath>
#include <functional>

#include "common/grid.hpp"
#include "roughness/noise.hpp"

namespace mcmd::test {

// A 2^n+1 grid holding f(x, y) everywhere, every cell known.
inline Grid grid_of(int n, const std::function<double(int, int)>& f) {
  Grid g(n);
  for (int y = 0; y < g.side(); ++y)
    for (int x = 0; x < g.side(); ++x) {
      g.z(x, y) = f(x, y);
      g.state(x, y) = CellState::known;
    }
  return g;
}

// Two smooth peaks and a valley: terrain-like, not polynomial.
inline double hills(int x, int y) {
  const double a = std::exp(-((x - 20.0) * (x - 20.0) + (y - 25.0) * (y - 25.0)) / 200.0);
  const double b = std::exp(-((x - 45.0) * (x - 45.0) + (y - 40.0) * (y - 40.0)) / 120.0);
  return 500.0 + 800.0 * a + 600.0 * b + 3.0 * x - 2.0 * y;
}

// Mark as unknown a disc and every cell whose hash falls under `drop`.
inline void punch_voids(Grid& g, double cx, double cy, double radius, double drop, std::uint64_t seed = 3) {
  for (int y = 0; y < g.side(); ++y)
    for (int x = 0; x < g.side(); ++x) {
      const bool in_disc = std::hypot(x - cx, y - cy) <= radius;
      const bool dropped = (hash_uniform(seed, x, y) + 1.0) / 2.0 < drop;
      if (in_disc || dropped) {
        g.state(x, y) = CellState::unknown;
        g.z(x, y) = 0.0;
      }
    }
}

}  // namespace mcmd::test
