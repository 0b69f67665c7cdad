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
//     4-point cubic interpolation of the coarser level, then a few Gauss-Seidel
//     sweeps relax them towards the discrete thin-plate surface (2 at the
//     finest level, doubling per coarser level, at most 32). Only cells that
//     are constraints at that lattice position are pinned: pinning coarse
//     estimates is what makes a dimple lattice. On coarse levels the soft
//     estimates act as springs (stiffness ∝ constraint density) away from
//     pinned cells: they stand for the scattered samples a coarse lattice
//     cannot hold.
//  3. Multigrid (multigrid.cpp): conjugate gradients preconditioned by a
//     V-cycle at the finest level (constraint cells Dirichlet), to
//     convergence (a looser tolerance for large fields with no cell far from
//     data), on the thin-plate energy plus a weak pull towards the
//     cascade's fill: on large blob voids the plain converged thin plate
//     extends the rim's slopes too far (docs/default-method.md). Between
//     scattered samples a structure term (structure_term.cpp) then makes
//     valleys carry on along their own direction.
//  A field of at most a few dozen unknown cells skips 1-3: one dense solve
//  gives its exact thin plate (direct_plate.cpp).
//  4. Roughness (roughness/): with rs > 0 or rs auto, a constrained
//     fractal correction is added to the smooth fill in the same solve.
//
// The thin-plate energy keeps only the second differences that fit in the grid
// (natural boundary), so voids at the border stay bounded. Work runs over the
// runs of free cells only, so a raster with few voids is cheap. Everything is
// computed relative to the least-squares plane of the constraints (exact on
// planes, translation invariance, conditioning), in a fixed order: the same
// bits for any thread count (large lattices run in bands, lattice.hpp).
#include "thin_plate/thin_plate.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "common/distance.hpp"
#include "common/zero_runs.hpp"
#include "roughness/roughness.hpp"
#include "thin_plate/biharmonic_relax.hpp"
#include "thin_plate/cubic_prolong.hpp"
#include "thin_plate/direct_plate.hpp"
#include "thin_plate/lattice.hpp"
#include "thin_plate/multigrid.hpp"
#include "thin_plate/pull_push.hpp"
#include "thin_plate/structure_term.hpp"

namespace mcmd {

// The thin-plate energy ignores planes, so working on z - plane changes
// nothing in the limit, but makes every stage exact on planes and keeps the
// numbers small (fill(z + c) = fill(z) + c up to rounding).
Plane constraint_plane(const FieldView& f) {
  // Counts and coordinate sums are integers (exact in any order); the sums of
  // elevations run in raster order. Non-constraint cells add +0.0, which
  // changes no sum (none can be -0.0): a select, not a branch, per cell.
  std::int64_t n = 0, sx = 0, sy = 0;
  double sz = 0;
  for (int y = 0; y < f.h; ++y) {
    const CellState* state = f.state + f.index(0, y);
    const double* z = f.z + f.index(0, y);
    std::int64_t row_n = 0, row_sx = 0;
    for (int x = 0; x < f.w; ++x) {
      const bool c = is_constraint(state[x]);
      row_n += c;
      row_sx += c ? x : 0;
      sz += c ? z[x] : 0.0;
    }
    n += row_n; sx += row_sx; sy += row_n * y;
  }
  Plane p;
  if (n == 0) return p;
  const double count = static_cast<double>(n);
  p.x0 = static_cast<double>(sx) / count; p.y0 = static_cast<double>(sy) / count; p.c = sz / count;
  double xx = 0, xy = 0, yy = 0, xz = 0, yz = 0;
  for (int y = 0; y < f.h; ++y) {
    const CellState* state = f.state + f.index(0, y);
    const double* z = f.z + f.index(0, y);
    const double dy = y - p.y0;
    for (int x = 0; x < f.w; ++x) {
      const bool c = is_constraint(state[x]);
      const double dx = c ? x - p.x0 : 0.0, dz = c ? z[x] - p.c : 0.0, ddy = c ? dy : 0.0;
      xx += dx * dx; xy += dx * ddy; yy += ddy * ddy; xz += dx * dz; yz += ddy * dz;
    }
  }
  const double det = xx * yy - xy * xy;
  if (det > 1e-9 * (xx * yy + 1e-300)) {
    p.cx = (yy * xz - xy * yz) / det;
    p.cy = (xx * yz - xy * xz) / det;
  } else if (xx > 0 && yy == 0) {  // all on one row (a 1-row field): the line along it
    p.cx = xz / xx;
  } else if (yy > 0 && xx == 0) {  // all on one column
    p.cy = yz / yy;
  }
  return p;
}

namespace {

// Coarsest (2×2) first; levels.back() is the field, relative to `ref`.
std::vector<Lattice> build_hierarchy(const FieldView& f, const Plane& ref) {
  Lattice finest;
  finest.w = f.w;
  finest.h = f.h;
  const std::size_t cells = static_cast<std::size_t>(f.w) * f.h;
  finest.z.resize(cells);
  finest.pinned.resize(cells);
  for (int y = 0; y < f.h; ++y) {  // a select per cell, not a branch: it vectorises
    const CellState* state = f.state + f.index(0, y);
    const double* z = f.z + f.index(0, y);
    double* out = finest.z.data() + finest.index(0, y);
    std::uint8_t* pinned = finest.pinned.data() + finest.index(0, y);
    for (int x = 0; x < f.w; ++x) {
      const bool constraint = is_constraint(state[x]);
      const double value = z[x] - ref.at(x, y);
      pinned[x] = constraint;
      out[x] = constraint ? value : 0.0;
    }
  }
  finest.spans = free_spans(finest.pinned, finest.w, finest.h);
  std::vector<Lattice> levels;
  levels.push_back(std::move(finest));
  while (levels.back().w > 2 || levels.back().h > 2) levels.push_back(coarser_lattice(levels.back()));
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
  std::vector<double> run;
  for (const Span& sp : lat.spans) {
    run.resize(static_cast<std::size_t>(sp.x1 - sp.x0));
    prolong_run(coarse.z.data(), coarse.w, coarse.h, sp.y, sp.x0, sp.x1, run.data());
    for (int x = sp.x0; x < sp.x1; ++x) {
      const std::size_t i = lat.index(x, sp.y);
      const double p = run[static_cast<std::size_t>(x - sp.x0)];
      const bool is_new = (x & 1) || (sp.y & 1);
      if (est && start == CascadeStart::blend && is_new) {
        const double w = est->weight[i];
        lat.z[i] = w * est->mean[i] + (1.0 - w) * p;
      } else {
        lat.z[i] = p;
      }
    }
  }
}

// Soft estimates as springs on a coarse level's free cells, as stiff as the
// density of constraints they summarise. Only where the lattice itself has no
// constraint next to the cell: there the estimate stands for constraints the
// lattice cannot hold (scattered samples); beside pinned cells (void rims) the
// lattice already knows the data and a blurred estimate only flattens the fill.
void attach_springs(Lattice& lat, const PullLevel& est, double strength) {
  lat.spring.assign(est.weight.size(), 0.0);
  lat.target = est.mean;
  for (const Span& sp : lat.spans)
    for (int x = sp.x0; x < sp.x1; ++x) {
      bool near_pinned = false;
      for (int dy = -1; dy <= 1 && !near_pinned; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          const int nx = x + dx, ny = sp.y + dy;
          if (nx >= 0 && ny >= 0 && nx < lat.w && ny < lat.h && lat.pinned[lat.index(nx, ny)]) {
            near_pinned = true;
            break;
          }
        }
      const std::size_t i = lat.index(x, sp.y);
      if (!near_pinned) lat.spring[i] = strength * est.weight[i];
    }
}

// Springs of stiffness pull_length⁻⁴ from every free cell to its current value.
void attach_pull(Lattice& lat, double pull_length) {
  lat.spring.clear();
  lat.spring_all = 1.0 / std::pow(pull_length, 4.0);
  lat.target = lat.z;
}

// Whether the field is shallow: large, with every free cell within
// shallow_reach of a constraint (the caller's farthest distance, a Chebyshev
// bound, or one distance transform, paid only by fields large enough to gain
// from it; all three decide alike).
bool shallow_field(const Lattice& finest, double farthest, const ThinPlateSchedule& s) {
  if (finest.free_count() < s.shallow_min_free) return false;
  if (farthest >= 0) return farthest <= s.shallow_reach;
  // A sufficient test first, a few byte passes: every free cell within r along
  // both axes lies within r·√2 <= shallow_reach (scattered samples, 3.3 % kept).
  const int r = static_cast<int>(std::floor(s.shallow_reach / std::sqrt(2.0)));
  if (all_within_chebyshev(finest.pinned.data(), finest.w, finest.h, r)) return true;
  const std::vector<double> dist = distance_to_valid(finest.pinned.data(), finest.w, finest.h);
  for (const Span& sp : finest.spans)
    for (int x = sp.x0; x < sp.x1; ++x)
      if (dist[finest.index(x, sp.y)] > s.shallow_reach) return false;
  return true;
}

// The finest level's solve: CG to the field's tolerance; on a shallow field
// the looser shallow one, and the structure term after structure_after
// iterations (a new Krylov space: the operator changes).
void solve_finest(Multigrid& mg, Lattice& fine, double farthest, const ThinPlateSchedule& s,
                  const ProgressFn& progress) {
  const bool loose = s.shallow_pcg_tol > s.pcg_tol || s.structure_strength > 1.0;
  const bool shallow = loose && shallow_field(fine, farthest, s);
  const double tol = shallow ? std::max(s.pcg_tol, s.shallow_pcg_tol) : s.pcg_tol;
  if (!shallow || !(s.structure_strength > 1.0)) {
    mg.solve_pcg(fine, tol, s.pcg_max_iterations, progress);
    return;
  }
  mg.solve_pcg(fine, tol, s.structure_after, sub_progress(progress, 0.0, 0.6));
  const StructureTerm term(fine, s.structure_strength, s.vcycle.threads);
  mg.solve_pcg(fine, 0.0, s.structure_iterations, sub_progress(progress, 0.6, 1.0), &term);
}

// The part of the finest lattice its solve touches: the free cells' bounding
// box grown by the stencil's reach (2 cells), clipped. Every second difference
// through a free cell fits inside it, so the solve there is the solve on the
// whole field; the known cells beyond only fed the coarse levels. A void in a
// wide field (its box plus margins, void_field.hpp) then costs what its box
// costs at the finest level.
struct FreeBox {
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;  // [x0, x1) × [y0, y1)
  bool whole(const Lattice& lat) const { return x0 == 0 && y0 == 0 && x1 == lat.w && y1 == lat.h; }
};

FreeBox free_box(const Lattice& lat) {
  constexpr int reach = 2;
  FreeBox b{lat.w, lat.spans.front().y, 0, lat.spans.back().y + 1};
  for (const Span& sp : lat.spans) {
    b.x0 = std::min(b.x0, sp.x0);
    b.x1 = std::max(b.x1, sp.x1);
  }
  return FreeBox{std::max(0, b.x0 - reach), std::max(0, b.y0 - reach), std::min(lat.w, b.x1 + reach),
                 std::min(lat.h, b.y1 + reach)};
}

Lattice crop(const Lattice& lat, const FreeBox& b) {
  Lattice sub;
  sub.w = b.x1 - b.x0;
  sub.h = b.y1 - b.y0;
  sub.tension = lat.tension;
  sub.z.reserve(static_cast<std::size_t>(sub.w) * sub.h);
  sub.pinned.reserve(sub.z.capacity());
  for (int y = b.y0; y < b.y1; ++y) {
    const std::size_t from = lat.index(b.x0, y), to = lat.index(b.x1, y);
    sub.z.insert(sub.z.end(), lat.z.begin() + from, lat.z.begin() + to);
    sub.pinned.insert(sub.pinned.end(), lat.pinned.begin() + from, lat.pinned.begin() + to);
  }
  sub.spans.reserve(lat.spans.size());
  for (const Span& sp : lat.spans) sub.spans.push_back(Span{sp.y - b.y0, sp.x0 - b.x0, sp.x1 - b.x0});
  return sub;
}

// d added to the field's unknown cells (d is 0 outside its box).
void add_to_unknown(const FieldView& field, const Displacement& d) {
  for (int y = d.y0; y < d.y0 + d.h; ++y) {
    const double* v = d.values.data() + static_cast<std::size_t>(y - d.y0) * d.w;
    for (int x = d.x0; x < d.x0 + d.w; ++x)
      if (!is_constraint(field.state_at(x, y))) field.z_at(x, y) += v[x - d.x0];
  }
}

int cascade_sweeps(const ThinPlateSchedule& s, int depth_from_finest) {
  long long sweeps = s.finest_sweeps;
  for (int d = 0; d < depth_from_finest && sweeps < s.max_sweeps; ++d) sweeps *= 2;
  return static_cast<int>(std::min<long long>(sweeps, s.max_sweeps));
}

// The smooth fill, with `added` (null: nothing) added to each unknown cell
// as it is written: thin_plate_with_roughness's + d, with no pass of its own.
void smooth_fill(const FieldView& field, const Displacement* added, const ThinPlateSchedule& schedule,
                 const ProgressFn& progress) {
  if (field.w < 1 || field.h < 1) return;
  if (schedule.tension == 0.0 &&
      direct_thin_plate(field.w, field.h, field.z, field.state, schedule.direct_max_unknown)) {
    if (added) add_to_unknown(field, *added);
    report(progress, 1.0);
    return;
  }
  const Plane ref = field.own_plane ? constraint_plane(field) : Plane{};
  std::vector<Lattice> levels = build_hierarchy(field, ref);
  const int finest = static_cast<int>(levels.size()) - 1;
  if (levels[finest].spans.empty()) return;
  for (int k = 0; k <= finest; ++k) levels[k].tension = schedule.tension * std::ldexp(1.0, 2 * (finest - k));

  // 1. Bottom-up soft estimates.
  const std::vector<PullLevel> estimates = pull(levels[finest]);
  report(progress, 0.05);

  // 2. Top-down cascade.
  if (finest == 0) {  // a 2×2 grid: the mean of its constraints
    const PullLevel flat{levels[0].w, levels[0].h, std::vector<double>(levels[0].z.size(), 0.0),
                       std::vector<double>(levels[0].z.size(), 0.0)};
    start_coarsest(levels[0], flat);
  } else {
    start_coarsest(levels[0], estimates[0]);
  }
  if (finest > 0 && schedule.spring > 0) attach_springs(levels[0], estimates[0], schedule.spring);
  const int threads = schedule.vcycle.threads;
  relax(levels[0], nullptr, cascade_sweeps(schedule, finest), schedule.omega, threads);
  for (int k = 1; k <= finest; ++k) {
    start_from_coarser(levels[k], levels[k - 1], k < finest ? &estimates[k] : nullptr, schedule.start);
    if (k < finest && schedule.spring > 0) attach_springs(levels[k], estimates[k], schedule.spring);
    relax(levels[k], nullptr, cascade_sweeps(schedule, finest - k), schedule.omega, threads);
    report(progress, 0.05 + 0.35 * k / finest);
  }

  // 3. Finest level: the thin plate with a soft pull towards the cascade's
  // fill, solved to convergence (a well-posed problem; deep inside large
  // voids the pull keeps the coarse levels' estimate instead of extending
  // the rim's slopes, docs/default-method.md).
  const FreeBox box = free_box(levels[finest]);
  const bool whole = box.whole(levels[finest]);
  Lattice cropped = whole ? Lattice{} : crop(levels[finest], box);
  Lattice& fine = whole ? levels[finest] : cropped;
  if (schedule.pull_length > 0) attach_pull(fine, schedule.pull_length);
  VCycleSchedule cycles = schedule.vcycle;
  if (schedule.pcg_tol <= 0) cycles.coarse_pin = CoarsePin::neighbourhood;  // soft corrections overshoot alone
  Multigrid mg(fine, cycles);
  if (schedule.pcg_tol > 0) {
    solve_finest(mg, fine, field.farthest, schedule, sub_progress(progress, 0.4, 0.8));
    report(progress, 0.8);
  } else {
    for (int c = 0; c < schedule.v_cycles; ++c) {
      mg.v_cycle(fine);
      report(progress, 0.4 + 0.4 * (c + 1) / schedule.v_cycles);
    }
  }

  for (const Span& sp : fine.spans) {
    const int fy = sp.y + box.y0;  // box is the whole field when not cropped
    for (int x = sp.x0; x < sp.x1; ++x) {
      const int fx = x + box.x0;
      field.z_at(fx, fy) = fine.z[fine.index(x, sp.y)] + ref.at(fx, fy);
    }
    if (!added || fy < added->y0 || fy >= added->y0 + added->h) continue;
    const int x0 = std::max(sp.x0 + box.x0, added->x0), x1 = std::min(sp.x1 + box.x0, added->x0 + added->w);
    const double* v = added->values.data() + static_cast<std::size_t>(fy - added->y0) * added->w;
    double* z = field.z + field.index(0, fy);
    for (int x = x0; x < x1; ++x) z[x] += v[x - added->x0];  // in cache: just written
  }
  report(progress, 1.0);
}

}  // namespace

void thin_plate_smooth(const FieldView& field, const ThinPlateSchedule& schedule, const ProgressFn& progress) {
  smooth_fill(field, nullptr, schedule, progress);
}

void thin_plate_with_roughness(const FieldView& field, long long x0, long long y0, const FillParams& params,
                               const ThinPlateSchedule& schedule, const ProgressFn& progress) {
  Displacement d;
  if (adds_roughness(params))
    d = roughness_displacement(
        RoughField{field.w, field.h, x0, y0, field.z, field.state, field.wanted, field.farthest}, params,
        schedule.vcycle.threads);
  if (d.empty()) return thin_plate_smooth(field, schedule, progress);
  // S(z − d) + d: the constraints are shifted for the solve, then restored
  // (d is 0 outside its box); the solve adds d to the unknown cells as it
  // writes them. The displaced constraints are found eight cells at a time
  // (scattered samples: a few in a hundred cells) and listed.
  std::vector<std::size_t> shifted;
  std::vector<double> kept;
  for (int y = d.y0; y < d.y0 + d.h; ++y) {
    const std::size_t row = static_cast<std::size_t>(y) * field.w + d.x0;
    const double* v = d.values.data() + static_cast<std::size_t>(y - d.y0) * d.w;
    detail::for_each_constraint(field.state + row, d.w, [&](int x) {
      if (v[x] == 0.0) return;
      shifted.push_back(row + static_cast<std::size_t>(x));
      kept.push_back(field.z[row + x]);
      field.z[row + x] -= v[x];
    });
  }
  smooth_fill(field, &d, schedule, progress);
  for (std::size_t k = 0; k < shifted.size(); ++k) field.z[shifted[k]] = kept[k];
}

void thin_plate_fill_scheduled(Grid& grid, const FillParams& params, const ThinPlateSchedule& schedule,
                               const ProgressFn& progress) {
  const FieldView field{grid.side(), grid.side(), grid.elevations().data(), grid.states().data()};
  thin_plate_with_roughness(field, grid.origin_x(), grid.origin_y(), params, schedule, progress);
  report(progress, 1.0);
}

void thin_plate_fill(Grid& grid, const FillParams& params, const ProgressFn& progress) {
  thin_plate_fill_scheduled(grid, params, ThinPlateSchedule{}, progress);
}

}  // namespace mcmd
