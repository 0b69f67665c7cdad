// The default method (`-method mcmd`): MCMD's structure — a bottom-up pass that
// builds coarse estimates from the constraint cells on the nested 2^l+1
// hierarchy, then a top-down pass that fills the unknown cells level by level —
// with ingredients chosen by measurement against gdal_fillnodata
// (docs/default-method.md has the numbers).
//
//  1. Bottom-up (pull_push.cpp): the constraint cells (known, ridge, river) are
//     restricted up the hierarchy as weighted sums, giving every level a soft
//     estimate (weighted mean + confidence), MDBU's role.
//  2. Top-down cascade (cubic_prolong.cpp, biharmonic_relax.cpp): from the
//     coarsest lattice (2×2) to the grid, each level's free cells start from the
//     4-point cubic interpolation of the coarser level (blended with the soft
//     estimate where that is confident), then a few Gauss-Seidel sweeps relax
//     them towards the discrete thin-plate surface, more sweeps on coarse
//     levels. Only cells that are constraints at that lattice position are
//     pinned: pinning coarse estimates is what makes a dimple lattice.
//  3. Multigrid (multigrid.cpp): V-cycles at the finest level finish the
//     constrained thin-plate solve (constraint cells Dirichlet).
//  4. Roughness (roughness.cpp): with rs > 0 or rs auto, a constrained
//     fractal correction is added to the smooth fill.
//
// The thin-plate energy keeps only the second differences that fit in the grid
// (natural boundary), so voids at the border stay bounded. Work runs over the
// runs of free cells only, so a raster with few voids is cheap. Everything is
// computed relative to the mean of the constraints (translation invariance and
// conditioning), single-threaded and in a fixed order (deterministic).
#include "mcmd/thin_plate.hpp"

#include <algorithm>
#include <cstddef>
#include <vector>

#include "mcmd/biharmonic_relax.hpp"
#include "mcmd/cubic_prolong.hpp"
#include "mcmd/lattice.hpp"
#include "mcmd/multigrid.hpp"
#include "mcmd/pull_push.hpp"
#include "mcmd/roughness.hpp"
#include "mcmd/thin_plate_schedule.hpp"

namespace mcmd {

namespace {

double constraint_mean(const Grid& grid) {
  double sum = 0.0;
  std::size_t n = 0;
  for (std::size_t i = 0; i < grid.cell_count(); ++i)
    if (is_constraint(grid.states()[i])) {
      sum += grid.elevations()[i];
      ++n;
    }
  return n ? sum / static_cast<double>(n) : 0.0;
}

// levels[k] has side 2^k + 1; levels.back() is the grid, relative to `ref`.
std::vector<Lattice> build_hierarchy(const Grid& grid, double ref) {
  Lattice finest;
  finest.side = grid.side();
  finest.z.assign(grid.cell_count(), 0.0);
  finest.pinned.assign(grid.cell_count(), 0);
  for (std::size_t i = 0; i < grid.cell_count(); ++i)
    if (is_constraint(grid.states()[i])) {
      finest.pinned[i] = 1;
      finest.z[i] = grid.elevations()[i] - ref;
    }
  finest.spans = free_spans(finest.pinned, finest.side);
  std::vector<Lattice> levels;
  levels.push_back(std::move(finest));
  while (levels.back().side > 2) levels.push_back(coarser_lattice(levels.back()));
  std::reverse(levels.begin(), levels.end());
  return levels;
}

// Coarsest level: the soft estimate, or the mean of the estimates where a
// corner has none.
void start_coarsest(Lattice& lat, const PullLevel& est) {
  double sum = 0.0, wsum = 0.0;
  for (std::size_t i = 0; i < est.mean.size(); ++i) {
    sum += est.weight[i] * est.mean[i];
    wsum += est.weight[i];
  }
  const double fallback = wsum > 0 ? sum / wsum : 0.0;
  for (const Span& sp : lat.spans)
    for (int x = sp.x0; x < sp.x1; ++x) {
      const std::size_t i = lat.index(x, sp.y);
      lat.z[i] = est.weight[i] > 0 ? est.mean[i] : fallback;
    }
}

// `est` is null at the finest level (its estimate is the constraints only).
void start_from_coarser(Lattice& lat, const Lattice& coarse, const PullLevel* est, CascadeStart start) {
  for (const Span& sp : lat.spans)
    for (int x = sp.x0; x < sp.x1; ++x) {
      const std::size_t i = lat.index(x, sp.y);
      const double p = prolong_at(coarse.z.data(), coarse.side, x, sp.y);
      const bool is_new = (x & 1) || (sp.y & 1);
      if (est && start == CascadeStart::blend && is_new) {
        const double w = est->weight[i];
        lat.z[i] = w * est->mean[i] + (1.0 - w) * p;
      } else {
        lat.z[i] = p;
      }
    }
}

// Soft estimates as springs on a coarse level's free cells.
void attach_springs(Lattice& lat, const PullLevel& est, double strength) {
  lat.spring.resize(est.weight.size());
  for (std::size_t i = 0; i < est.weight.size(); ++i) lat.spring[i] = strength * est.weight[i];
  lat.target = est.mean;
}

int cascade_sweeps(const ThinPlateSchedule& s, int depth_from_finest) {
  long long sweeps = s.finest_sweeps;
  for (int d = 0; d < depth_from_finest && sweeps < s.max_sweeps; ++d) sweeps *= 2;
  return static_cast<int>(std::min<long long>(sweeps, s.max_sweeps));
}

}  // namespace

void thin_plate_fill_scheduled(Grid& grid, const FillParams& params, const ThinPlateSchedule& schedule,
                               const ProgressFn& progress) {
  const double ref = constraint_mean(grid);
  std::vector<Lattice> levels = build_hierarchy(grid, ref);
  const int finest = static_cast<int>(levels.size()) - 1;
  if (levels[finest].spans.empty()) return;

  // 1. Bottom-up soft estimates.
  const std::vector<PullLevel> estimates = pull(levels[finest]);
  report(progress, 0.05);

  // 2. Top-down cascade.
  if (finest == 0) {  // a 2×2 grid: the mean of its constraints
    const PullLevel flat{2, std::vector<double>(4, 0.0), std::vector<double>(4, 0.0)};
    start_coarsest(levels[0], flat);
  } else {
    start_coarsest(levels[0], estimates[0]);
  }
  if (finest > 0 && schedule.spring > 0) attach_springs(levels[0], estimates[0], schedule.spring);
  relax(levels[0], nullptr, cascade_sweeps(schedule, finest), schedule.omega);
  for (int k = 1; k <= finest; ++k) {
    start_from_coarser(levels[k], levels[k - 1], k < finest ? &estimates[k] : nullptr, schedule.start);
    if (k < finest && schedule.spring > 0) attach_springs(levels[k], estimates[k], schedule.spring);
    relax(levels[k], nullptr, cascade_sweeps(schedule, finest - k), schedule.omega);
    report(progress, 0.05 + 0.35 * k / finest);
  }

  // 3. Multigrid V-cycles at the finest level.
  Multigrid mg(levels[finest], schedule.vcycle);
  for (int c = 0; c < schedule.v_cycles; ++c) {
    mg.v_cycle(levels[finest]);
    report(progress, 0.4 + 0.4 * (c + 1) / schedule.v_cycles);
  }

  // 4. Roughness on the smooth fill.
  Lattice& fill = levels[finest];
  if (params.rs_auto || params.rs > 0) add_roughness(fill, grid, params);

  std::vector<double>& z = grid.elevations();
  for (std::size_t i = 0; i < z.size(); ++i)
    if (!fill.pinned[i]) z[i] = fill.z[i] + ref;
  report(progress, 1.0);
}

void thin_plate_fill(Grid& grid, const FillParams& params, const ProgressFn& progress) {
  thin_plate_fill_scheduled(grid, params, ThinPlateSchedule{}, progress);
}

}  // namespace mcmd
