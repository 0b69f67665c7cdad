// The ridge particles of the skeleton (skeleton.hpp, seed 001 §2.1).
#pragma once

#include <cstdint>
#include <vector>

namespace mcmd::terrain {

struct RoutePoint {
  double x, y;    // cell coordinates (cell centres at integers)
  double height;  // altitude above the relief's base
};

struct RidgeRoutes {
  std::vector<std::vector<RoutePoint>> routes;  // one per particle, from its start
  std::vector<double> height;                   // per cell: a route's height there (the highest), < 0: none
  std::vector<int> owner;                       // per cell: the couple whose route it is, -1: none
  int couples = 0;                              // couples started
};

// `couples` couples on a w×h raster, start heights in [0.75, 1] · top.
// Deterministic in (seed, arguments), couples run one after the other.
RidgeRoutes run_ridge_particles(int w, int h, int couples, double H, double top, std::uint64_t seed);

// σ of the altitude's Gaussian: a quarter of the raster's larger side.
double ridge_sigma(int w, int h);

}  // namespace mcmd::terrain
