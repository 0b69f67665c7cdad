#include "terrain/methods/plate_terrain.hpp"

#include <vector>

#include "terrain/methods/displacement.hpp"
#include "thin_plate/thin_plate.hpp"

namespace mcmd::terrain {

void plate_terrain(Canvas& c, const TerrainParams& p, double unit, const ProgressFn& progress,
                   const std::vector<double>& relief_scale) {
  std::vector<double> d = terrain_displacement(c, p, unit);
  for (std::size_t i = 0; i < relief_scale.size() && i < d.size(); ++i) d[i] *= relief_scale[i];
  report(progress, 0.2);
  if (c.constraints() == 0) {
    c.z = d;
    report(progress, 1.0);
    return;
  }
  // The solve runs on z − d at the constraints; their own z is never touched.
  std::vector<double> shifted(c.cells());
  for (std::size_t i = 0; i < shifted.size(); ++i) shifted[i] = is_constraint(c.state[i]) ? c.z[i] - d[i] : 0.0;
  ThinPlateSchedule schedule;
  schedule.vcycle.threads = p.threads;
  const FieldView field{c.w, c.h, shifted.data(), c.state.data()};
  thin_plate_smooth(field, schedule, sub_progress(progress, 0.2, 1.0));
  for (std::size_t i = 0; i < shifted.size(); ++i)
    if (!is_constraint(c.state[i])) c.z[i] = shifted[i] + d[i];
}

}  // namespace mcmd::terrain
