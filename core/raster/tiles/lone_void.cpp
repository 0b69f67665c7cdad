#include "raster/tiles/lone_void.hpp"

#include <algorithm>
#include <cstddef>
#include <stdexcept>

#include "common/distance.hpp"
#include "common/padding.hpp"
#include "thin_plate/schedule.hpp"
#include "thin_plate/thin_plate.hpp"

namespace mcmd::detail {

namespace {
int levels_for(int cells) {
  int n = 1;
  while ((1 << n) + 1 < cells) ++n;
  return n;
}
}  // namespace

int small_void_margin(int extent) { return kSmallVoidMargin + extent / kSmallVoidMarginDivisor; }

int max_small_extent(const TileLayout& layout) {
  const int window = layout.x.window_side();
  // Medium voids were worse solved alone than in windows on the blob
  // benchmark: box sides beyond half a tile at T = 129 (RMSE +1.4 %), beyond
  // kMaxSmallExtent at T = 513 (+1.1 %). Keep them in windows.
  const int cap = std::min(layout.x.step() / 2, kMaxSmallExtent);
  int e = 0;
  while (e < cap && e + 1 + 2 * small_void_margin(e + 1) <= window) ++e;
  return e;
}

int small_grid_reach(const TileLayout& layout) {
  const int e = max_small_extent(layout);
  return e < 1 ? 0 : ((1 << levels_for(e + 2 * small_void_margin(e))) + 1) / 2 + 1;
}

ComponentGrid component_grid(const Box& box, int width, int height) {
  ComponentGrid g;
  const int extent = std::max(box.width(), box.height());
  g.levels = levels_for(extent + 2 * small_void_margin(extent));
  const int side = (1 << g.levels) + 1;
  // Centred on the box (floor), a function of the box alone.
  g.ox = box.x0 + (box.width() - 1) / 2 - (side - 1) / 2;
  g.oy = box.y0 + (box.height() - 1) / 2 - (side - 1) / 2;
  int x0 = width, x1 = -1, y0 = height, y1 = -1;
  for (int u = 0; u < side; ++u) {
    const int x = reflect_index(static_cast<long long>(g.ox) + u, width);
    const int y = reflect_index(static_cast<long long>(g.oy) + u, height);
    x0 = std::min(x0, x);
    x1 = std::max(x1, x);
    y0 = std::min(y0, y);
    y1 = std::max(y1, y);
  }
  g.rect = ReadRect{x0, y0, x1 - x0 + 1, y1 - y0 + 1};
  return g;
}

std::vector<double> solve_component(const SmallComponent& c, const ComponentGrid& g, int width, int height,
                                    const double* z, const std::uint8_t* valid, const CoarseGuide& guide,
                                    double radius, const FillParams& params, const ProgressFn& progress,
                                    const std::vector<morph::LineCell>& lines) {
  const ReadRect& rect = g.rect;
  const std::size_t rw = static_cast<std::size_t>(rect.w);
  // The component's cells within the read rectangle.
  const std::vector<std::uint8_t> mine = run_mask(c.runs, rect.x0, rect.y0, rect.w, rect.h);

  Grid grid(g.levels, g.ox, g.oy);
  const int side = grid.side();
  std::vector<int> mx(side), my(side);
  for (int u = 0; u < side; ++u) {
    mx[u] = reflect_index(static_cast<long long>(g.ox) + u, width) - rect.x0;
    my[u] = reflect_index(static_cast<long long>(g.oy) + u, height) - rect.y0;
  }
  std::vector<std::uint8_t> known(grid.cell_count(), 0);
  auto& gz = grid.elevations();
  auto& gs = grid.states();
  for (int v = 0; v < side; ++v) {
    const std::size_t row = static_cast<std::size_t>(my[v]) * rw;
    for (int u = 0; u < side; ++u) {
      const std::size_t src = row + static_cast<std::size_t>(mx[u]);
      const std::size_t i = grid.index(u, v);
      if (valid[src]) {
        gz[i] = z[src];
        gs[i] = CellState::known;
        known[i] = 1;
      } else if (!mine[src]) {  // another void: the large-scale surface
        gz[i] = guide.at(static_cast<long long>(g.ox) + u, static_cast<long long>(g.oy) + v);
        gs[i] = CellState::known;
      }
    }
  }
  // Deep inside the component the guide is the surface, as in a window. Along
  // a row, a component cell is within (run length + 1) / 2 of a known cell.
  bool deep = false;
  for (const VoidRun& r : c.runs) deep = deep || (r.x1 - r.x0 + 1) / 2.0 > radius;
  if (deep) {
    const std::vector<double> dist = distance_to_valid(known.data(), side, side);
    for (std::size_t i = 0; i < dist.size(); ++i) {
      if (dist[i] <= radius || gs[i] != CellState::unknown) continue;
      const int u = static_cast<int>(i % side), v = static_cast<int>(i / side);
      gz[i] = guide.at(static_cast<long long>(g.ox) + u, static_cast<long long>(g.oy) + v);
      gs[i] = CellState::known;
    }
  }
  morph::place_line_cells(grid, lines);
  // The default method (the only one solving small voids alone), pinned as
  // a window is.
  ThinPlateSchedule schedule;
  schedule.pcg_tol = kPinnedPcgTolerance;
  thin_plate_fill_scheduled(grid, params, schedule, progress);

  std::vector<double> out;
  for (const VoidRun& r : c.runs)
    for (int x = r.x0; x < r.x1; ++x) out.push_back(grid.z(x - g.ox, r.y - g.oy));
  return out;
}

std::vector<double> solve_component_in_field(const SmallComponent& c, const Box& field, std::vector<double> z,
                                             const std::uint8_t* valid, const CoarseGuide& guide,
                                             const FillParams& params, const ProgressFn& progress,
                                             const std::vector<morph::LineCell>& lines) {
  const DeepPins pins{[&guide] { return &guide; }, field_pin_radius(guide.stride())};
  const RasterMorphology morphology{nullptr, 0, lines.empty() ? nullptr : &lines};
  VoidFieldResult r = solve_void_field(field, c.runs, std::move(z), valid, pins, params, 0.0, progress, 1, morphology);
  // A component solved alone is at most kMaxSmallExtent across: no cell
  // lies as far from data as reaches_far asks.
  if (r.values.empty()) throw std::logic_error("a small void component reached far from data");
  return std::move(r.values);
}

}  // namespace mcmd::detail
