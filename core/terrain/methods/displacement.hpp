// The displacement d of the default terrain method (plate_terrain.hpp), whose
// fill is F = S(z − d) + d with S the thin plate through the constraints: F
// keeps every constraint exactly and carries d's shape between them.
//   * relief: fractional Brownian motion (fbm.hpp), amplitude rs · unit for
//     the coarsest octave; near ridge and river cells each octave fades over
//     a distance about its spacing, so no octave tilts a crest or a valley
//     floor (the conditioning alone keeps their elevations, not the
//     cross-slope: a rough terrain would bury the lines);
//   * creases: a tent along ridge cells (falling away on both sides) and a
//     V along river cells (rising on both sides), saturating at a width of
//     an eighth of the raster: the paper's "ridged behaviour behind ridge
//     lines, bumped behind rivers", which a thin plate alone (smooth across
//     a line of constraints) does not give;
//   * lift (rt): rt · rs · unit away from every constraint, saturating like
//     the creases: > 0 raises, < 0 lowers the terrain between constraints.
#pragma once

#include <vector>

#include "mcmd/terrain.hpp"

namespace mcmd::terrain {

// The cross-slope of the creases at sharpness 1 (elevation per cell): the
// constraints' elevation range (or the relief's amplitude, if larger) over a
// quarter of the raster's larger side.
double crease_slope(const Canvas& canvas, double relief_amplitude);

// d for `canvas` (all zeros when there is nothing to add). `unit` is the
// elevation unit of params.fill.rs.
std::vector<double> terrain_displacement(const Canvas& canvas, const TerrainParams& params, double unit);

}  // namespace mcmd::terrain
