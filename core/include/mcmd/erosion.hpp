// Erosion of a synthesised terrain (core/terrain/erosion): landscape
// evolution that grows a drainage network into it. Each time step
//   * fills the closed depressions (Priority-Flood: sediment fills the
//     lakes), routes the water down the steepest descent (D8) and spreads
//     the drainage area over every lower neighbour (multiple flow
//     directions, so that hillslopes do not streak along the grid);
//   * uplifts the land and erodes it by the stream-power law
//     E = K·A^m·S^n (A the drainage area, S the slope to the receiver),
//     solved implicitly along the receivers from the outlets up (Braun &
//     Willett 2013): stable for any time step, O(cells) per step;
//   * relaxes the hillslopes: linear diffusion (soil creep), and slopes
//     steeper than the angle of repose fail (talus).
// It runs coarse to fine: the network converges on a coarse grid, then each
// finer grid starts from the coarser result plus the initial terrain's own
// finer detail and needs a few steps only; within a mirrored margin whose
// border is the outlet. At the end the initial terrain's finest octave,
// which creep rounded away, is put back (its texture). Constraint cells
// never change: sketch and point cells are held (water runs over them);
// ridge cells are divides and river cells carve their valleys, both warped
// back to their heights at the end, rivers still draining along their
// course and ridges still crests.
#pragma once

#include <vector>

#include "mcmd/progress.hpp"
#include "mcmd/terrain.hpp"

namespace mcmd {

// How the uplift is spread.
enum class UpliftPattern {
  terrain,  // in proportion to the uneroded terrain's height above its outlets: its mountains stay
  uniform,  // the same everywhere: a block dissected from its border
  map,      // ErosionParams::uplift_map, relative rates >= 0 per cell
};

struct ErosionParams {
  int steps = 0;            // time steps on the finest grid; 0: no erosion; kErodeAuto: the network converged
  double K = 0.0;           // erodibility; 0: automatic, the steady state keeps the terrain's relief
  double m = 0.5, n = 1.0;  // the stream-power exponents (m/n: the channels' concavity)
  UpliftPattern uplift = UpliftPattern::terrain;
  std::vector<double> uplift_map;  // UpliftPattern::map: w·h relative rates
  double diffusion = 1.0;   // hillslope diffusion, a factor of the default (0: none)
  double talus = 90.0;      // angle of repose in degrees, in (0, 90]; 90: none
  double cell_size = 30.0;  // a cell's side in elevation units (slopes and the talus angle need it)
  int threads = 1;          // for the warp back of the drawn lines (the steps run on one); the result does not depend on it
  // Put the uneroded terrain's finest octave back after the creep that
  // rounded it (its grain: small pits, no plastic sheen). Off for the paper
  // methods and MDI, whose finest octave is their subdivision's 2^k lattice.
  bool texture = true;
};

constexpr int kErodeAuto = -1;
constexpr int kMaxErodeSteps = 10000;

struct ErosionReport {
  int grids = 0;           // grids of the coarse-to-fine pyramid
  int steps = 0;           // steps on the finest grid
  int coarse_steps = 0;    // steps on the coarsest grid (the grids between are not eroded)
  bool converged = false;  // the coarsest grid's network (the valleys' layout) stopped changing
  double moved = 1.0;      // share of the finest grid's receivers that changed in its last step
  double K = 0.0;          // the erodibility used
};

// Throws std::invalid_argument naming the first bad parameter of p for a
// w×h terrain (one line).
void check_erosion(const ErosionParams& p, int w, int h);

// Erode `canvas` (every cell finite). Post: constraint cells and the border
// unchanged, every elevation finite; the same bits for any thread count.
// Throws std::invalid_argument for bad parameters, Cancelled.
ErosionReport erode(Canvas& canvas, const ErosionParams& params, const ProgressFn& progress = {});

}  // namespace mcmd
