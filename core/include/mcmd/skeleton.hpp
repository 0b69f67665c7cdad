// A skeleton of ridges and rivers made from scratch (Belhadj & Audibert 2005,
// seed 001 §2), the constraints of a terrain around it (Belhadj 2007 Fig. 11):
//  * ridge particle couples start back to back from random points, move one
//    cell per step with fractional-Brownian side impacts on their heading,
//    and lose altitude on a Gaussian of the distance covered (σ = a quarter
//    of the raster); a particle stops at the border, when its altitude is
//    spent, or where it meets another couple's route. The routes, blended
//    with Gaussian cross-profiles (σ/4), make the relief the rivers run on;
//  * river particles start near the top of the ridges and roll on that
//    relief (gravity along its slope, friction); one that reaches another
//    river joins it, one that leaves the raster drains, one that comes to
//    rest is dropped. Kept rivers carve in proportion to the particles
//    through them (their mass) and never climb downstream.
// Only the ridge and river cells are kept (the skeleton DEM), at the
// relief's elevation: ridge cells (CellState::ridge) and river cells
// (CellState::river), carved; synthesize() fills the rest.
#pragma once

#include <cstdint>
#include <vector>

#include "mcmd/progress.hpp"
#include "mcmd/terrain.hpp"

namespace mcmd {

struct SkeletonParams {
  int ridge_couples = 0;    // 0: automatic, about one per 80×80 cells' side (sqrt(w·h) / 80, at least 2)
  int river_particles = 0;  // 0: automatic, 6 per ridge couple
  double z_low = 0.0;       // elevation where the ridges' relief ends (the rivers' base level)
  double z_high = 1000.0;   // altitude of the highest ridge start
  double H = 0.5;           // of the side impacts: high H = smooth, long bends; low = jagged
  std::uint64_t seed = 0;
};

constexpr std::int64_t kNoRiver = -2;  // Skeleton::downstream of a cell that is no river cell
constexpr std::int64_t kExits = -1;    // of a river cell on the border whose river leaves the raster

struct Skeleton {
  Canvas canvas;                         // ridge and river cells, every other cell unknown
  std::vector<double> relief;            // the blended ridge relief the rivers ran on (w·h)
  std::vector<std::int64_t> downstream;  // per cell: the next river cell, kExits or kNoRiver
  int ridge_couples = 0;
  int rivers_kept = 0;     // rivers that drain to the border (directly or through another)
  int rivers_dropped = 0;  // came to rest in a hollow of the relief
};

// Throws std::invalid_argument for a bad size or parameters (z_high <= z_low).
Skeleton make_skeleton(int w, int h, const SkeletonParams& params, const ProgressFn& progress = {});

}  // namespace mcmd
