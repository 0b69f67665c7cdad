#include "raster/tiles/tile_window.hpp"

#include <algorithm>
#include <cstddef>

#include "common/distance.hpp"
#include "common/padding.hpp"
#include "method/fill_grid.hpp"

namespace mcmd {

namespace {

// Reflected raster coordinates of window cells [origin, origin + side).
std::vector<int> reflected(int origin, int side, int length) {
  std::vector<int> r(static_cast<std::size_t>(side));
  for (int u = 0; u < side; ++u) r[u] = reflect_index(static_cast<long long>(origin) + u, length);
  return r;
}

}  // namespace

double guide_radius(const TileLayout& layout, const CoarseGuide& guide) {
  // 8 guide strides (measured: 4 and 16 were worse on blob voids), kept inside
  // the halo so every window that outputs a cell sees the same known cells
  // within that radius.
  const double limit = layout.x.step() / 2 - layout.x.band() - 2;
  return std::max(1.0, std::min(kGuideRadiusStrides * guide.stride(), limit));
}

int exact_distance_limit(const TileLayout& layout) {
  return std::min(layout.x.step(), layout.y.step()) / 2 - layout.x.band();
}

ReadRect window_read_rect(const TileLayout& layout, int tx, int ty) {
  // Reflection maps a run of cells onto a run, so [min, max] covers them all.
  const std::vector<int> xs = reflected(layout.x.window_origin(tx), layout.x.window_side(), layout.x.length());
  const std::vector<int> ys = reflected(layout.y.window_origin(ty), layout.y.window_side(), layout.y.length());
  const auto [x0, x1] = std::minmax_element(xs.begin(), xs.end());
  const auto [y0, y1] = std::minmax_element(ys.begin(), ys.end());
  return ReadRect{*x0, *y0, *x1 - *x0 + 1, *y1 - *y0 + 1};
}

WindowResult solve_window(const TileLayout& layout, const WindowInput& in, const CoarseGuide* guide,
                          const FillParams& params, double max_distance, const ProgressFn& progress,
                          const std::vector<morph::LineCell>& lines) {
  const int ox = layout.x.window_origin(in.tx);
  const int oy = layout.y.window_origin(in.ty);
  Grid grid(layout.window_levels(), ox, oy);
  const int side = grid.side();
  const std::vector<int> mx = reflected(ox, side, layout.x.length());
  const std::vector<int> my = reflected(oy, side, layout.y.length());
  const std::size_t rw = static_cast<std::size_t>(in.rect.w);

  std::vector<std::uint8_t> known(grid.cell_count(), 0);
  for (int v = 0; v < side; ++v) {
    const std::size_t row = static_cast<std::size_t>(my[v] - in.rect.y0) * rw;
    for (int u = 0; u < side; ++u) {
      const std::size_t src = row + static_cast<std::size_t>(mx[u] - in.rect.x0);
      if (!in.valid[src]) continue;
      const std::size_t i = grid.index(u, v);
      grid.elevations()[i] = in.z[src];
      grid.states()[i] = CellState::known;
      known[i] = 1;
    }
  }
  const bool guided = guide && guide->ready();
  std::vector<double> dist;  // to the nearest known cell of the window
  if (guided || max_distance > 0) dist = distance_to_valid(known.data(), side, side);
  if (guided) {
    // Deep inside voids the guide is the surface: pin unknown cells farther
    // than the guide radius from any known cell of the window.
    const double radius = guide_radius(layout, *guide);
    for (std::size_t i = 0; i < dist.size(); ++i) {
      if (dist[i] <= radius) continue;
      const int u = static_cast<int>(i % side), v = static_cast<int>(i / side);
      grid.elevations()[i] = guide->at(mx[u], my[v]);
      grid.states()[i] = CellState::known;
    }
    // Pin the unknown cells of the outer 2-cell ring.
    for (int v = 0; v < side; ++v) {
      const bool ring_row = v < 2 || v >= side - 2;
      for (int u = 0; u < side; ++u) {
        if (!ring_row && u >= 2 && u < side - 2) {
          u = side - 3;  // skip to the right ring
          continue;
        }
        const std::size_t i = grid.index(u, v);
        if (grid.states()[i] != CellState::unknown) continue;
        grid.elevations()[i] = guide->at(mx[u], my[v]);
        grid.states()[i] = CellState::known;
      }
    }
  }
  morph::place_line_cells(grid, lines);
  if (grid.count(CellState::unknown) > 0) fill_grid(grid, params, progress);

  WindowResult r;
  r.tx = in.tx;
  r.ty = in.ty;
  r.xs = layout.x.region(in.tx);
  r.ys = layout.y.region(in.ty);
  const std::size_t cells = static_cast<std::size_t>(r.xs.size()) * r.ys.size();
  r.z.resize(cells);
  r.write.resize(cells);
  const bool beyond_window = guided && max_distance > exact_distance_limit(layout);
  std::size_t k = 0;
  for (int y = r.ys.begin; y < r.ys.end; ++y)
    for (int x = r.xs.begin; x < r.xs.end; ++x, ++k) {
      const std::size_t i = grid.index(x - ox, y - oy);
      r.z[k] = grid.elevations()[i];
      bool write = !known[i];
      // Beyond what the window sees, the guide's coarse distance decides.
      if (write && max_distance > 0 && !within_fill_distance(dist[i], max_distance))
        write = beyond_window && within_fill_distance(guide->coarse_distance(x, y), max_distance);
      r.write[k] = write ? 1 : 0;
    }
  return r;
}

}  // namespace mcmd
