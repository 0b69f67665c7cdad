// The river particles of the skeleton (skeleton.hpp, seed 001 §2.2): balls
// rolling on the ridge relief under gravity and friction, joining the
// rivers they reach. The seed backtracks the reached river and restarts it
// with the summed velocity and mass; here the reached river keeps its course
// below the junction (it already drains), so the network stays a tree whose
// every river cell drains to the border, and the mass only deepens it.
#pragma once

#include <cstdint>
#include <vector>

#include "terrain/skeleton/ridge_particles.hpp"
#include "terrain/skeleton/ridge_relief.hpp"

namespace mcmd::terrain {

struct RiverNetwork {
  std::vector<std::int64_t> downstream;  // per cell: the next river cell, kExits or kNoRiver (skeleton.hpp)
  std::vector<int> mass;                 // per cell: particles that flowed through it
  int kept = 0, dropped = 0;
};

// Particles start near the top of random ridge routes (in the order drawn,
// one after the other: deterministic); each kept river digs its valley in
// `relief` (RidgeRelief::dig).
RiverNetwork run_river_particles(int w, int h, const RidgeRoutes& routes, RidgeRelief& relief, double top,
                                 int particles, std::uint64_t seed);

}  // namespace mcmd::terrain
