// The time steps of one grid of the erosion: drain, stream power with
// uplift, hillslope diffusion and talus, until the drainage network stops
// changing or a step count is spent.
#pragma once

#include <cstdint>
#include <vector>

#include "mcmd/progress.hpp"
#include "terrain/erosion/pyramid.hpp"

namespace mcmd::terrain {

struct Evolution {
  double K = 0.0;          // erodibility (heights and lengths in finest cells); 0: a first guess from the network
  double m = 0.5, n = 1.0;
  double rate = 1.0;       // a factor of every uplift rate
  double relief = 0.0;     // > 0: steer `rate` so that relief() stays at this
  double gain = 0.5;       // how hard: rate /= (relief() / relief)^(gain·n) each step
  bool settle = true;      // converged only once the relief is within 1 % of its aim
  double hillslope = 1.0;  // the hillslope length ℓ in finest cells: diffusion D = K·ℓ²
  double diffusion = 1.0;  // a factor of D
  double courant = 1.0;    // a step is this many cells² of creep on its grid
  double talus = 0.0;      // the slope of repose (tangent); 0: none
  int threads = 1;
};

struct GridRun {
  int steps = 0;
  bool converged = false;
  double moved = 1.0;  // share of the channels whose receiver changed in the last step
};

// The lowest of z's fixed cells (the base level), HUGE_VAL without any.
double lowest_fixed(const std::vector<double>& z, const ErosionGrid& g);

// How high the free cells of g's raster (its margin aside) stand above its
// lowest fixed cell: their 99th percentile (on a sample).
double relief(const std::vector<double>& z, const ErosionGrid& g);

// Steps on grid g from z (heights in finest cells): at most max_steps, fewer
// when `until_converged` and the network and the relief stopped changing.
// Updates e.K (its first guess) and e.rate (the relief's steering).
GridRun evolve(std::vector<double>& z, const ErosionGrid& g, Evolution& e, int max_steps, bool until_converged,
               const ProgressFn& progress);

}  // namespace mcmd::terrain
