// synthesize(): the checks shared by every terrain method, the unit of rs,
// and the dispatch (plate_terrain.hpp, paper_terrain.hpp).
#include <cmath>
#include <stdexcept>

#include "mcmd/terrain.hpp"
#include "terrain/methods/paper_terrain.hpp"
#include "terrain/methods/plate_terrain.hpp"

namespace mcmd {

namespace {

void check_params(const Canvas& c, const TerrainParams& p) {
  check_terrain_size(c.w, c.h);
  if (c.z.size() != c.cells() || c.state.size() != c.cells())
    throw std::invalid_argument("the canvas does not hold one elevation and one state per cell");
  const FillParams& f = p.fill;
  const double values[] = {f.known_shape.I, f.known_shape.I_bu, f.ridge_shape.I, f.ridge_shape.I_bu,
                           f.river_shape.I, f.river_shape.I_bu, f.H, f.rt, f.rs, f.noise_unit, p.sharpness};
  for (double v : values)
    if (!std::isfinite(v)) throw std::invalid_argument("terrain parameters must be finite numbers");
  if (f.rs < 0 || f.noise_unit < 0 || p.sharpness < 0)
    throw std::invalid_argument("rs, its unit and the sharpness must be >= 0");
  if (f.rs_auto) throw std::invalid_argument("rs auto measures known terrain: a terrain is made, give rs");
  for (double z : c.z)
    if (!std::isfinite(z)) throw std::invalid_argument("constraint elevations must be finite numbers");
}

// The elevation unit of rs: its own, or the constraints' range.
double rs_unit(const Canvas& c, const TerrainParams& p) {
  if (p.fill.noise_unit > 0 || p.fill.rs == 0) return p.fill.noise_unit;
  const double range = constraint_range(c);
  if (range > 0) return range;
  throw std::invalid_argument(
      "the roughness is a fraction of the constraints' elevation range, which is 0 here: give it in "
      "elevation units instead (e.g. -rs 300m, RS=300m)");
}

}  // namespace

void synthesize(Canvas& c, const TerrainParams& p, const ProgressFn& progress) {
  check_params(c, p);
  report(progress, 0.0);
  if (p.method == TerrainMethod::none || c.count(CellState::unknown) == 0) {
    report(progress, 1.0);
    return;
  }
  const double unit = rs_unit(c, p);
  if (c.constraints() == 0 && p.fill.rs == 0)
    throw std::invalid_argument("no constraint and no roughness: the terrain would be flat (give -rs, RS)");
  if (p.method == TerrainMethod::mcmd)
    terrain::plate_terrain(c, p, unit, progress);
  else
    terrain::paper_terrain(c, p, unit, progress);
  report(progress, 1.0);
}

}  // namespace mcmd
