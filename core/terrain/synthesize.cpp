// synthesize(): the checks shared by every terrain method, the unit of rs,
// and the dispatch (plate_terrain.hpp, paper_terrain.hpp).
#include <cmath>
#include <stdexcept>
#include <utility>
#include <vector>

#include "mcmd/terrain.hpp"
#include "terrain/methods/measured_relief.hpp"
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

// rs auto: the relief measured from the known cells, as an amplitude in
// elevation units (and its factor per cell, `scale`).
FillParams measured(const Canvas& c, const TerrainParams& p, std::vector<double>& scale) {
  if (p.method != TerrainMethod::mcmd)
    throw std::invalid_argument("rs auto is measured for the default method (mcmd): give the paper methods a number (e.g. -rs 0.2, RS=0.2)");
  terrain::MeasuredRelief m = terrain::measure_relief(c, p.fill.seed, p.fill.H, p.threads);
  FillParams f = p.fill;
  f.rs_auto = false;
  f.rs = m.amplitude > 0 ? 1.0 : 0.0;
  f.noise_unit = m.amplitude;
  f.H = m.H;
  scale = std::move(m.scale);
  return f;
}

}  // namespace

void synthesize(Canvas& c, const TerrainParams& given, const ProgressFn& progress) {
  check_params(c, given);
  report(progress, 0.0);
  if (given.method == TerrainMethod::none || c.count(CellState::unknown) == 0) {
    report(progress, 1.0);
    return;
  }
  TerrainParams p = given;
  std::vector<double> relief_scale;
  if (p.fill.rs_auto) p.fill = measured(c, p, relief_scale);
  const double unit = rs_unit(c, p);
  if (c.constraints() == 0 && p.fill.rs == 0)
    throw std::invalid_argument("no constraint and no roughness: the terrain would be flat (give -rs, RS)");
  if (p.method == TerrainMethod::mcmd)
    terrain::plate_terrain(c, p, unit, progress, relief_scale);
  else
    terrain::paper_terrain(c, p, unit, progress);
  report(progress, 1.0);
}

}  // namespace mcmd
