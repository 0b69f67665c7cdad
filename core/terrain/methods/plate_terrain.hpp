// The default terrain method (TerrainMethod::mcmd): the thin plate of the
// default fill method through the constraints, carrying the displacement of
// displacement.hpp: F = S(z − d) + d. Constraint cells are kept exactly;
// without any constraint the terrain is d itself.
#pragma once

#include <vector>

#include "mcmd/progress.hpp"
#include "mcmd/terrain.hpp"

namespace mcmd::terrain {

// Pre: unit > 0 when params.fill.rs > 0. Post: as synthesize().
// `relief_scale`: empty, or a factor of the displacement at every cell (rs
// auto's, measured_relief.hpp).
void plate_terrain(Canvas& canvas, const TerrainParams& params, double unit, const ProgressFn& progress,
                   const std::vector<double>& relief_scale = {});

}  // namespace mcmd::terrain
