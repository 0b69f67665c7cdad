#include "raster/tiles/tile_plan.hpp"

#include <algorithm>
#include <optional>
#include <stdexcept>

#include "mcmd/fill_raster.hpp"
#include "raster/frame.hpp"
#include "raster/tiles/lone_void.hpp"
#include "raster/tiles/tile_scan.hpp"

namespace mcmd::detail {

namespace {

// Only tiles whose output region meets a large component's box need a window.
void needs_of_large(const TileLayout& layout, const std::vector<Box>& large, std::vector<std::uint8_t>& needs) {
  std::fill(needs.begin(), needs.end(), 0);
  for (const Box& b : large)
    for (int ty = 0; ty < layout.y.count(); ++ty) {
      const Range ry = layout.y.region(ty);
      if (ry.end <= b.y0 || ry.begin > b.y1) continue;
      for (int tx = 0; tx < layout.x.count(); ++tx) {
        const Range rx = layout.x.region(tx);
        if (rx.end > b.x0 && rx.begin <= b.x1) needs[static_cast<std::size_t>(ty) * layout.x.count() + tx] = 1;
      }
    }
}

// No job for the voids left unfilled (-inner, -maxvoid): a tile whose output
// region holds only left voids, a small component all of whose cells are
// left. Every cell that is filled still gets the same windows, so the same
// bits (a window's region is where it is blended).
void skip_left_voids(const LeftVoids& left, ScanResult& scan, std::vector<SmallComponent>& small) {
  if (left.empty()) return;
  for (std::size_t t = 0; t < scan.needs.size(); ++t) scan.needs[t] &= scan.needs_filled[t];
  std::erase_if(small, [&left](const SmallComponent& c) { return left.count(c.runs) == cell_count(c.runs); });
}

}  // namespace

namespace {

void start_plan(int width, int height, Method method, const TilingParams& tiling, RasterFillStats& stats,
                TilePlan& plan) {
  plan.layout = TileLayout(width, height, effective_tile_side(width, height, tiling.tile_side, method));
  const TileLayout& layout = plan.layout;
  plan.single = layout.tile_count() == 1;
  if (!plan.single) plan.guide = CoarseGuide(width, height, guide_stride(width, height));
  stats.tile_side = layout.tile_side();
  stats.tiles_x = layout.x.count();
  stats.tiles_y = layout.y.count();
}

// Small void components are solved alone (docs/tiling.md, "Small voids"):
// the default method only, with a guide (several tiles), without -md.
std::optional<ComponentFinder> component_finder(const TilePlan& plan, const FillParams& params,
                                                const TilingParams& tiling) {
  const int small_extent = max_small_extent(plan.layout);
  std::optional<ComponentFinder> finder;
  if (!plan.single && params.method == Method::mcmd && tiling.max_distance == 0 && small_extent >= 1)
    finder.emplace(plan.layout.x.length(), small_extent);
  return finder;
}

// After pass 1: the guide's solve, the small components and the jobs
// (`route_in_fields`: with -morph auto, the components' channels).
bool finish_plan(const RasterAccess& raster, const FillParams& params, const TilingParams& tiling,
                 const ProgressFn& progress, RasterFillStats& stats, TilePlan& plan, const LeftVoids& left,
                 ScanResult& scan, std::optional<ComponentFinder>& finder, bool route_in_fields) {
  const TileLayout& layout = plan.layout;
  if (finder) {
    finder->finish();
    if (finder->overflow()) finder.reset();
  }
  stats.void_cells = scan.voids;
  stats.known_cells = scan.known;
  if (scan.voids == 0) return false;
  if (scan.known == 0) throw std::invalid_argument("the raster has no known cell to fill from");
  check_range(scan.lo, scan.hi);

  if (!raster.lines.empty()) plan.lines = morph::line_cells(raster);
  // One noise unit for every window, so displacement amplitudes agree across seams.
  plan.params = params;
  plan.params.morph.channels = false;  // until small components are known (below)
  if (plan.params.noise_unit <= 0) plan.params.noise_unit = scan.hi - scan.lo;
  if (!plan.single) {
    plan.guide.solve(plan.params, progress, effective_threads(tiling.threads));
    stats.guide_stride = plan.guide.stride();
    if (tiling.max_distance > exact_distance_limit(layout)) plan.guide.prepare_distance();
  }
  const bool guided = !plan.single && plan.guide.ready();
  if (finder && guided) {
    plan.small = std::move(finder->small());
    std::vector<VoidRun> runs;
    for (const SmallComponent& c : plan.small) runs.insert(runs.end(), c.runs.begin(), c.runs.end());
    plan.small_runs = RunsByRow(std::move(runs), raster.height);
    needs_of_large(layout, finder->large(), scan.needs);
  }
  skip_left_voids(left, scan, plan.small);
  for (std::size_t c = 0; c < plan.small.size(); ++c) plan.jobs.push_back(Job{true, c});
  for (std::size_t t = 0; t < scan.needs.size(); ++t)
    if (scan.needs[t]) plan.jobs.push_back(Job{false, t});
  stats.windows_solved = plan.jobs.size() - plan.small.size();
  stats.small_components = plan.small.size();
  // -morph auto: channels are routed through the small components, each
  // solved in its void field as in a raster filled whole (void_field.hpp);
  // the windows (larger voids) fill without them.
  plan.params.morph.channels = params.morph.channels && route_in_fields && !plan.small.empty();
  if (plan.params.morph.channels && plan.params.morph.min_inflow <= 0)
    plan.params.morph.min_inflow = default_channel_cells(scan.known);
  stats.channels_skipped = params.morph.channels && (!plan.params.morph.channels || stats.windows_solved > 0);
  plan.radius = guided ? guide_radius(layout, plan.guide) : 0.0;
  return true;
}

// A raster of `voids`' cells as voids, every other cell known (at 0): what
// pass 1 needs besides the elevations, for a plan built from chunks.
RasterAccess void_pattern(int width, int height, const RunsByRow& voids) {
  RasterAccess r;
  r.width = width;
  r.height = height;
  r.read = [&voids](int x0, int y0, int w, int h, double* z, std::uint8_t* valid) {
    const std::size_t n = static_cast<std::size_t>(w) * h;
    std::fill_n(z, n, 0.0);
    std::fill_n(valid, n, std::uint8_t{1});
    voids.clear(x0, y0, w, h, valid);
  };
  r.write = [](int, int, int, int, const double*, const std::uint8_t*) {};
  return r;
}

}  // namespace

bool plan_tiles(const RasterAccess& raster, const FillParams& params, const TilingParams& tiling,
                const ProgressFn& progress, RasterFillStats& stats, TilePlan& plan, const LeftVoids& left) {
  start_plan(raster.width, raster.height, params.method, tiling, stats, plan);
  std::optional<ComponentFinder> finder = component_finder(plan, params, tiling);
  ScanResult scan = scan_raster(raster, plan.layout, plan.single ? nullptr : &plan.guide,
                                sub_progress(progress, 0.0, 2.0 / 3), finder ? &*finder : nullptr, &left,
                                effective_threads(tiling.threads));
  return finish_plan(raster, params, tiling, sub_progress(progress, 2.0 / 3, 1.0), stats, plan, left, scan, finder,
                     true);
}

bool plan_from_parts(const PlanParts& parts, const FillParams& params, const TilingParams& tiling,
                     RasterFillStats& stats, TilePlan& plan, LeftVoids& left) {
  start_plan(parts.width, parts.height, params.method, tiling, stats, plan);
  if (!plan.single) parts.set_guide(plan.guide);
  std::optional<ComponentFinder> finder = component_finder(plan, params, tiling);
  const RasterAccess pattern = void_pattern(parts.width, parts.height, parts.voids);
  left = selects_voids(tiling) ? find_left_voids(pattern, tiling) : LeftVoids{};
  ScanResult scan = scan_void_runs(parts.voids, plan.layout, finder ? &*finder : nullptr, &left);
  scan.lo = parts.lo;
  scan.hi = parts.hi;
  // A chunk's halo holds a component's grid, not its void field: no channels.
  return finish_plan(pattern, params, tiling, {}, stats, plan, left, scan, finder, false);
}

}  // namespace mcmd::detail
