#include "raster/void_field.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>

#include "common/distance.hpp"
#include "common/zero_runs.hpp"
#include "morphology/channel_fill.hpp"
#include "morphology/channels.hpp"
#include "thin_plate/thin_plate.hpp"

namespace mcmd::detail {

int longest_void_run(const std::uint8_t* valid, int w, int h) {
  int longest = 0;
  for (int y = 0; y < h; ++y) {
    for_each_zero_run(valid + static_cast<std::size_t>(y) * w, w,
                      [&](int x0, int x1) { longest = std::max(longest, x1 - x0); });
  }
  return longest;
}

int void_field_margin(int extent) { return std::min(kVoidFieldMargin, 8 + 2 * extent) + extent; }

Box void_field_rect(const Box& box, int width, int height) {
  const int m = void_field_margin(std::max(box.width(), box.height()));
  return Box{std::max(0, box.x0 - m), std::max(0, box.y0 - m), std::min(width - 1, box.x1 + m),
             std::min(height - 1, box.y1 + m)};
}

namespace {

// The guide's value at cell i of the field `rect` (row-major).
double guide_at(const CoarseGuide& guide, const Box& rect, std::size_t i) {
  const auto w = static_cast<std::size_t>(rect.width());
  return guide.at(rect.x0 + static_cast<long long>(i % w), rect.y0 + static_cast<long long>(i / w));
}

// The cells of other voids inside a field would be solved again in their own
// fields (the blob benchmark's fields held 4.6× the raster's void cells).
// Where they outnumber the component's own cells (and are more than a few),
// they are pinned to the coarse guide, as deep cells are; the component is
// then the field's only unknown. Blob RMSE ratio 0.7990 → 0.7992, half-dome
// blobs' solves 80 → 45 ms (docs/tiling.md).
void pin_other_voids(const Box& rect, const std::vector<std::uint8_t>& own, std::size_t own_count,
                     const DeepPins& pins, std::vector<double>& z, std::vector<CellState>& state) {
  if (!pins.guide) return;
  std::size_t others = 0;
  for (std::size_t i = 0; i < state.size(); ++i) others += state[i] == CellState::unknown && !own[i];
  if (others < std::max(own_count, kPinOthersMin)) return;
  const CoarseGuide* guide = pins.guide();
  if (!guide || !guide->ready()) return;
  for (std::size_t i = 0; i < state.size(); ++i) {
    if (state[i] != CellState::unknown || own[i]) continue;
    z[i] = guide_at(*guide, rect, i);
    state[i] = CellState::known;
  }
}

// The field's part of the raster-wide inflow.
std::vector<double> crop(const RasterMorphology& m, const Box& rect) {
  std::vector<double> out;
  out.reserve(static_cast<std::size_t>(rect.width()) * rect.height());
  for (int y = rect.y0; y <= rect.y1; ++y) {
    const double* row = m.inflow + static_cast<std::size_t>(y) * m.width;
    out.insert(out.end(), row + rect.x0, row + rect.x1 + 1);
  }
  return out;
}

// The line cells of the field's unknown cells, as field indices.
std::vector<morph::FieldLineCell> line_cells_in(const RasterMorphology& m, const Box& rect,
                                                 const std::vector<CellState>& state) {
  std::vector<morph::FieldLineCell> out;
  if (!m.lines) return out;
  const auto [b, e] = morph::cells_in_rows(*m.lines, rect.y0, rect.height());
  for (std::size_t k = b; k < e; ++k) {
    const morph::LineCell& c = (*m.lines)[k];
    if (c.x < rect.x0 || c.x > rect.x1) continue;
    const std::int32_t i = (c.y - rect.y0) * rect.width() + (c.x - rect.x0);
    if (state[i] == CellState::unknown) out.push_back({i, c.kind, c.z, c.place});
  }
  return out;
}

}  // namespace

double field_pin_radius(int guide_stride) {
  return kGuideRadiusStrides * std::max(kMinGuideStride, guide_stride);
}

VoidFieldResult solve_void_field(const Box& rect, const std::vector<VoidRun>& runs, std::vector<double> z,
                                 const std::uint8_t* valid, const DeepPins& pins, const FillParams& params,
                                 double max_distance, const ProgressFn& progress, int threads,
                                 const RasterMorphology& morphology) {
  const int w = rect.width(), h = rect.height();
  const std::size_t cells = static_cast<std::size_t>(w) * h;
  const auto at = [&](int x, int y) { return static_cast<std::size_t>(y - rect.y0) * w + (x - rect.x0); };
  ThinPlateSchedule schedule;
  schedule.vcycle.threads = threads;
  // Distances are needed for -md, deep pins and the far-void check; a field
  // whose void runs are all short needs none of them (most small voids), nor
  // does one whose every cell is near data by a cheaper bound (scattered
  // samples: 3 % kept cells have runs of 100+ cells but no cell 12 from data).
  double reach = (longest_void_run(valid, w, h) + 1) / 2.0;
  // (Only where it can pay: a field large enough to be shallow, or one that
  // would otherwise need the transform.)
  const bool large = cells - static_cast<std::size_t>(std::count(valid, valid + cells, 1)) >= schedule.shallow_min_free;
  if (const int r = static_cast<int>(schedule.shallow_reach / std::sqrt(2.0));
      reach > r * std::sqrt(2.0) && (large || reach > pins.radius) && all_within_chebyshev(valid, w, h, r))
    reach = r * std::sqrt(2.0);
  const bool may_pin = pins.guide && reach > pins.radius;
  const bool need_dist = max_distance > 0 || may_pin || reaches_far(reach);
  // Exact: a void cell's nearest known cell is next to its component.
  const std::vector<double> dist = need_dist ? distance_to_valid(valid, w, h) : std::vector<double>{};
  VoidFieldResult out;
  out.farthest = reach;
  if (need_dist) {
    out.farthest = 0.0;
    for (const VoidRun& run : runs)
      for (int x = run.x0; x < run.x1; ++x) out.farthest = std::max(out.farthest, dist[at(x, run.y)]);
  }
  if (reaches_far(out.farthest)) return out;
  const CoarseGuide* guide = nullptr;
  if (may_pin) {
    const bool deep = std::any_of(dist.begin(), dist.end(), [&](double d) { return d > pins.radius; });
    if (deep) guide = pins.guide();
  }
  const bool pinned = guide && guide->ready();

  std::vector<CellState> state(cells);
  for (std::size_t i = 0; i < cells; ++i) {
    state[i] = valid[i] ? CellState::known : CellState::unknown;
    if (pinned && dist[i] > pins.radius) {
      z[i] = guide_at(*guide, rect, i);
      state[i] = CellState::known;
    }
  }
  const std::vector<std::uint8_t> own = run_mask(runs, rect.x0, rect.y0, w, h);  // the component's cells
  pin_other_voids(rect, own, cell_count(runs), pins, z, state);
  FieldView view{w, h, z.data(), state.data()};
  view.wanted = own.data();  // the roughness is made around these only
  if (!need_dist) {
    view.farthest = reach <= schedule.shallow_reach ? reach : -1.0;  // else the solver measures
  } else if (!pinned) {  // the distances are to the constraints: pass them on
    view.farthest = 0.0;
    for (std::size_t i = 0; i < cells; ++i) view.farthest = std::max(view.farthest, dist[i]);
  }
  // Roughness, if any, is keyed on raster coordinates (roughness.hpp); its
  // statistics come from the field: the void and its margin.
  const std::vector<morph::FieldLineCell> lines = line_cells_in(morphology, rect, state);
  if (params.morph.channels || !lines.empty()) {  // with -morph auto, at least drained
    // The drainage into the voids: the raster's, or the field's own (the
    // field holds the void's surroundings up to min(32, 8 + 2·extent) +
    // extent cells away: on the hydrology benchmark it found the same
    // inflows as the whole raster's).
    const std::vector<double> inflow = !params.morph.channels ? std::vector<double>{}
                                       : morphology.inflow    ? crop(morphology, rect)
                                                              : morph::inflow_into_voids(z.data(), valid, w, h);
    morph::fill_with_morphology(view, rect.x0, rect.y0, own.data(), inflow.empty() ? nullptr : inflow.data(), lines,
                                params, schedule, progress);
  } else {
    thin_plate_with_roughness(view, rect.x0, rect.y0, params, schedule, progress);
  }
  for (const VoidRun& run : runs)
    for (int x = run.x0; x < run.x1; ++x) {
      const std::size_t i = at(x, run.y);
      out.values.push_back(z[i]);
      out.write.push_back(within_fill_distance(need_dist ? dist[i] : 0.0, max_distance) ? 1 : 0);
    }
  return out;
}

}  // namespace mcmd::detail
