// erode(): the checks and the coarse-to-fine landscape evolution
// (mcmd/erosion.hpp).
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "mcmd/erosion.hpp"
#include "terrain/erosion/evolve.hpp"
#include "terrain/erosion/line_guard.hpp"
#include "terrain/erosion/margin.hpp"
#include "terrain/erosion/pyramid.hpp"
#include "terrain/erosion/texture.hpp"
#include "thin_plate/thin_plate.hpp"

namespace mcmd {

namespace {

using terrain::ErosionGrid;

// The length of the hillslopes between the smallest valleys, in elevation
// units (metres on a DEM in metres), at least two cells of the grid
// (evolve.hpp): diffusion D = K·ℓ² balances the stream power there.
constexpr double kHillslopeLength = 50.0;
// Steps at most: on the coarsest grid (until its network converges) and
// on the finest with EROSION=auto. The finest grid's valleys are in place
// after a few steps: at 1025² the realism measures of 5, 8 and 19 steps
// agree within their noise, while its channels keep moving (a few % a
// step, their share scales with the step).
// The grids between are not eroded, only carried through: their steps
// wore away the small valleys that the initial terrain's detail seeds on
// the finest grid (1025² from scratch, three seeds: drainage density 0.50
// with 10 steps on the grid between, 0.56 with 3, 0.59 with none; real
// mountains 0.66-1.49) and took a fifth of the time.
constexpr int kCoarsestSteps = 300, kAutoSteps = 8;
// The finest grid's network comes mostly from the coarsest; its steps
// are three cells² of creep long, and its smallest valleys form in a third
// of the steps (as seen side by side with steps of one: the same valleys).
constexpr double kFinestCourant = 3.0;
// The drainage area each river cell brings, in finest cells: a river of a
// few hundred cells drains like a trunk valley of its raster.
constexpr double kRiverSource = 100.0;

[[noreturn]] void bad(const std::string& why) { throw std::invalid_argument(why); }

// The finest grid: heights in cells; the border fixed as the outlets, the
// sketch and point cells held. The drawn lines erode with the land, and are
// warped back at the end: held at their heights, the land beside a ridge
// would rise above it and the land beside a river sink below it. Instead
// they guide the water: a ridge is a divide (no water enters it), a river
// brings water of its own and carves its valley.
ErosionGrid finest(const Canvas& c, const ErosionParams& p) {
  ErosionGrid g;
  g.w = c.w, g.h = c.h;
  g.initial.resize(c.cells());
  g.fixed.resize(c.cells());
  for (int y = 0; y < c.h; ++y)
    for (int x = 0; x < c.w; ++x) {
      const std::size_t i = c.index(x, y);
      g.initial[i] = c.z[i] / p.cell_size;
      const CellState s = c.state[i];
      const bool line = s == CellState::ridge || s == CellState::river;
      g.fixed[i] = is_constraint(s) && !line ? 2 : terrain::on_border(x, y, c.w, c.h) ? 1 : 0;
      if (s == CellState::ridge) {
        if (g.guides.divide.empty()) g.guides.divide.assign(c.cells(), 0);
        g.guides.divide[i] = 1;
      }
      if (s == CellState::river) {
        if (g.guides.source.empty()) g.guides.source.assign(c.cells(), 0.0);
        g.guides.source[i] = kRiverSource;
      }
    }
  return g;
}

// The uplift pattern, scaled to a mean of 1 over the free cells.
std::vector<double> uplift_of(const ErosionGrid& g, const ErosionParams& p) {
  std::vector<double> u(g.initial.size(), 1.0);
  if (p.uplift == UpliftPattern::map) u = p.uplift_map;
  if (p.uplift == UpliftPattern::terrain) {
    // The height of the uneroded terrain above its lowest cell, with a floor
    // so that no free cell is left without uplift (it would stay flat).
    const std::vector<double>& z = g.initial;
    const auto [lo, hi] = std::minmax_element(z.begin(), z.end());
    const double range = *hi > *lo ? *hi - *lo : 1.0;
    for (std::size_t i = 0; i < u.size(); ++i) u[i] = 0.1 + (z[i] - *lo) / range;
  }
  double sum = 0.0;
  std::size_t free = 0;
  for (std::size_t i = 0; i < u.size(); ++i)
    if (!g.fixed[i]) sum += u[i], ++free;
  if (free == 0 || sum <= 0.0) return std::vector<double>(u.size(), 0.0);
  for (double& v : u) v *= static_cast<double>(free) / sum;
  return u;
}

// The finer grid's start: the coarser result, plus the initial terrain's
// detail that the coarser grid cannot hold; fixed cells at their heights.
std::vector<double> refine(const std::vector<double>& z, const ErosionGrid& coarse, const ErosionGrid& fine) {
  std::vector<double> up = terrain::prolong(z, coarse.w, coarse.h, fine.w, fine.h);
  const std::vector<double> smooth = terrain::prolong(coarse.initial, coarse.w, coarse.h, fine.w, fine.h);
  for (std::size_t i = 0; i < up.size(); ++i)
    up[i] = fine.fixed[i] ? fine.initial[i] : up[i] + (fine.initial[i] - smooth[i]);
  return up;
}

// The free cells stretched about the lowest fixed cell to the relief aimed
// at: the finest grid's valleys, cut deeper than the coarsest grid's,
// lower it, which a stronger steering of its uplift makes swing.
void hold_relief(std::vector<double>& z, const ErosionGrid& g, double aim) {
  const double now = terrain::relief(z, g);
  if (!(now > 0)) return;
  const double lo = terrain::lowest_fixed(z, g);
  const double stretch = aim / now;
  for (std::size_t i = 0; i < z.size(); ++i)
    if (!g.fixed[i]) z[i] = lo + (z[i] - lo) * stretch;
}

// The eroded heights (finest cells) into the canvas. The line cells eroded
// with the land: a smooth warp, the thin plate through their residuals (0
// at the other constraints), brings them back exactly.
void write_back(Canvas& c, const std::vector<double>& z, const ErosionGrid& g, double cell_size, int threads) {
  std::vector<double> warp(c.cells(), 0.0);
  bool ridges = false;
  for (std::size_t i = 0; i < c.cells(); ++i)
    if ((c.state[i] == CellState::ridge || c.state[i] == CellState::river) && !g.fixed[i])
      warp[i] = c.z[i] - z[i] * cell_size, ridges = true;
  if (ridges) {
    ThinPlateSchedule schedule;
    schedule.vcycle.threads = threads;
    thin_plate_smooth(FieldView{c.w, c.h, warp.data(), c.state.data()}, schedule);
  }
  for (std::size_t i = 0; i < c.cells(); ++i)
    if (!is_constraint(c.state[i])) c.z[i] = z[i] * cell_size + warp[i];
  terrain::keep_ridges_crests(c);
  terrain::keep_rivers_draining(c);
}

}  // namespace

void check_erosion(const ErosionParams& p, int w, int h) {
  if (p.steps != kErodeAuto && (p.steps < 0 || p.steps > kMaxErodeSteps))
    bad("the erosion steps must be auto or a whole number in [0, " + std::to_string(kMaxErodeSteps) + "]");
  if (!std::isfinite(p.K) || p.K < 0) bad("the erodibility K must be a number >= 0 (0: automatic)");
  if (!std::isfinite(p.m) || p.m < 0 || p.m > 2) bad("the stream-power exponent m must be in [0, 2]");
  if (!std::isfinite(p.n) || p.n < 0.5 || p.n > 4) bad("the stream-power exponent n must be in [0.5, 4]");
  if (!std::isfinite(p.diffusion) || p.diffusion < 0 || p.diffusion > 100)
    bad("the hillslope diffusion must be a factor in [0, 100]");
  if (!std::isfinite(p.talus) || p.talus <= 0 || p.talus > 90) bad("the talus angle must be in (0, 90] degrees");
  if (!std::isfinite(p.cell_size) || p.cell_size <= 0) bad("the cell size must be a number > 0");
  if (p.uplift == UpliftPattern::map) {
    if (p.uplift_map.size() != static_cast<std::size_t>(w) * h) bad("the uplift map must hold one rate per cell");
    for (double u : p.uplift_map)
      if (!std::isfinite(u) || u < 0) bad("the uplift map's rates must be finite numbers >= 0");
  }
}

namespace {

// erode() on a canvas that already has its margin of `margin` cells.
ErosionReport erode_all(Canvas& canvas, int margin, const ErosionParams& p, const ProgressFn& progress) {
  ErosionReport out;
  std::vector<ErosionGrid> grids{finest(canvas, p)};
  grids[0].margin = margin;
  grids[0].uplift = uplift_of(grids[0], p);
  while (std::max(grids.back().w, grids.back().h) > terrain::kCoarsestSide) grids.push_back(terrain::coarser(grids.back()));
  out.grids = static_cast<int>(grids.size());

  terrain::Evolution e;
  e.K = p.K;
  e.m = p.m, e.n = p.n;
  // With K automatic the relief of the uneroded terrain is held; a given K
  // lets the relief follow from it and the uplift.
  if (p.K == 0.0) e.relief = terrain::relief(grids[0].initial, grids[0]);
  e.hillslope = kHillslopeLength / p.cell_size;
  e.diffusion = p.diffusion;
  e.talus = p.talus >= 90 ? 0.0 : std::tan(p.talus * M_PI / 180.0);
  // The steps on one thread: most of a step walks the drainage order (the
  // area, the implicit heights), and a second thread, spinning between the
  // row loops it shares, doubled the CPU time and, on a busy machine, the
  // wall time too (1025², load 4-5 on 2 cores: 1.8 s CPU and 3.9 s wall on
  // one thread, 4.0 s CPU and 8.1 s wall on two). The warp back uses them.
  e.threads = 1;

  std::vector<double> z;
  const std::size_t levels = grids.size();
  for (std::size_t l = levels; l-- > 0;) {
    const ErosionGrid& g = grids[l];
    z = l + 1 == levels ? g.initial : refine(z, grids[l + 1], g);
    const bool coarsest = l + 1 == levels, last = l == 0;
    if (!coarsest && !last) continue;
    // The coarsest grid settles the relief; the finest only corrects it
    // gently (harder, it swings), hold_relief() the rest.
    e.gain = coarsest ? 0.5 : 0.15;
    e.settle = coarsest;
    e.courant = last && !coarsest ? kFinestCourant : 1.0;
    const int max_steps = last && p.steps != kErodeAuto ? p.steps : coarsest ? kCoarsestSteps : kAutoSteps;
    // Progress: the coarsest grid the first half, the finest the rest.
    const double lo = last ? 0.5 : 0.0, hi = last ? 1.0 : 0.5;
    const terrain::GridRun run = evolve(z, g, e, max_steps, !last || p.steps == kErodeAuto, sub_progress(progress, lo, hi));
    if (coarsest) out.converged = run.converged;
    if (last) out.steps = run.steps, out.moved = run.moved;
    else out.coarse_steps += run.steps;
  }
  out.K = e.K;
  if (e.relief > 0) hold_relief(z, grids[0], e.relief);
  if (p.texture) terrain::restore_texture(z, grids[0]);
  write_back(canvas, z, grids[0], p.cell_size, std::max(1, p.threads));
  return out;
}

}  // namespace

ErosionReport erode(Canvas& canvas, const ErosionParams& p, const ProgressFn& progress) {
  check_erosion(p, canvas.w, canvas.h);
  for (double z : canvas.z)
    if (!std::isfinite(z)) bad("the terrain to erode must be finite everywhere");
  report(progress, 0.0);
  if (p.steps == 0 || canvas.w < 3 || canvas.h < 3) {
    report(progress, 1.0);
    return {};
  }
  const int m = terrain::margin_of(canvas.w, canvas.h);
  Canvas big = terrain::with_margin(canvas, m);
  ErosionParams q = p;
  if (p.uplift == UpliftPattern::map) q.uplift_map = terrain::with_margin(p.uplift_map, canvas.w, canvas.h, m);
  const ErosionReport out = erode_all(big, m, q, progress);
  terrain::without_margin(big, m, canvas);
  report(progress, 1.0);
  return out;
}

}  // namespace mcmd
