#include "raster/tiles/tile_window.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>

#include "common/distance.hpp"
#include "common/padding.hpp"
#include "method/fill_grid.hpp"
#include "thin_plate/schedule.hpp"
#include "thin_plate/thin_plate.hpp"

namespace mcmd {

namespace {

// Reflected raster coordinates of window cells [origin, origin + side).
std::vector<int> reflected(int origin, int side, int length) {
  std::vector<int> r(static_cast<std::size_t>(side));
  for (int u = 0; u < side; ++u) r[u] = reflect_index(static_cast<long long>(origin) + u, length);
  return r;
}

// [x0, x1) × [y0, y1) in window cells.
struct WindowRect {
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  int w() const { return x1 - x0; }
  int h() const { return y1 - y0; }
  bool holds(int u, int v) const { return u >= x0 && u < x1 && v >= y0 && v < y1; }
};

// What the default method solves of a window: the tile's output region grown
// by one blend band on every side. Every cell the blend takes from the window
// then has at least one band of context, and no cell is solved twice beyond
// the bands (a 193² field at T = 129 instead of the 257² window). The paper
// methods need the whole 2^n+1 window.
WindowRect solved_rect(const TileLayout& layout, const WindowInput& in, int ox, int oy, int side) {
  const Range rx = layout.x.region(in.tx), ry = layout.y.region(in.ty);
  const int bx = layout.x.band(), by = layout.y.band();
  return WindowRect{std::max(0, rx.begin - ox - bx), std::max(0, ry.begin - oy - by),
                    std::min(side, rx.end - ox + bx), std::min(side, ry.end - oy + by)};
}

// A bound on every cell's distance to a known cell of `known` inside `rect`,
// when all lie within `reach` (Euclidean) by a Chebyshev test; -1 otherwise.
double near_bound(const std::vector<std::uint8_t>& known, int side, const WindowRect& rect, double reach) {
  const int r = static_cast<int>(std::floor(reach / std::sqrt(2.0)));
  if (r < 1) return -1.0;
  std::vector<std::uint8_t> sub(static_cast<std::size_t>(rect.w()) * rect.h());
  for (int v = 0; v < rect.h(); ++v)
    std::copy_n(known.begin() + static_cast<std::ptrdiff_t>(v + rect.y0) * side + rect.x0, rect.w(),
                sub.begin() + static_cast<std::ptrdiff_t>(v) * rect.w());
  return all_within_chebyshev(sub.data(), rect.w(), rect.h(), r) ? r * std::sqrt(2.0) : -1.0;
}

// Pins unknown cells of the window to the guide: with `dist` (the distance to
// the window's known cells; may be empty when no cell is that far), those
// farther than `radius`, since deep inside voids the guide is the surface;
// then the unknown cells of the outer 2-cell ring, so every window is
// constrained. Returns the largest distance left unpinned inside `rect`.
double pin_to_guide(Grid& grid, const std::vector<double>& dist, double radius, const WindowRect& rect,
                    const std::vector<int>& mx, const std::vector<int>& my, const CoarseGuide& guide) {
  const int side = grid.side();
  const auto pin = [&](int u, int v) {
    const std::size_t i = grid.index(u, v);
    grid.elevations()[i] = guide.at(mx[u], my[v]);
    grid.states()[i] = CellState::known;
  };
  double farthest = 0.0;
  if (!dist.empty())
    for (int v = 0; v < side; ++v)
      for (int u = 0; u < side; ++u) {
        const double d = dist[grid.index(u, v)];
        if (d > radius) pin(u, v);
        else if (rect.holds(u, v)) farthest = std::max(farthest, d);
      }
  for (int v = 0; v < side; ++v) {
    const bool ring_row = v < 2 || v >= side - 2;
    for (int u = 0; u < side; u = ring_row || u != 1 ? u + 1 : std::max(2, side - 2))  // skip the inside
      if (grid.states()[grid.index(u, v)] == CellState::unknown) pin(u, v);
  }
  return farthest;
}

// The default method on `rect` of the window, its unknown outer 2-cell ring
// pinned to the guide like the window's own ring; the result is written back
// into the window.
void fill_solved_rect(Grid& grid, const WindowRect& rect, const std::vector<int>& mx, const std::vector<int>& my,
                      const CoarseGuide& guide, const FillParams& params, double farthest,
                      const ProgressFn& progress) {
  const int w = rect.w(), h = rect.h();
  std::vector<double> z(static_cast<std::size_t>(w) * h);
  std::vector<CellState> state(z.size());
  bool any_unknown = false;
  for (int v = 0; v < h; ++v)
    for (int u = 0; u < w; ++u) {
      const std::size_t i = grid.index(rect.x0 + u, rect.y0 + v), j = static_cast<std::size_t>(v) * w + u;
      z[j] = grid.elevations()[i];
      state[j] = grid.states()[i];
      if (state[j] != CellState::unknown) continue;
      if (u < 2 || v < 2 || u >= w - 2 || v >= h - 2) {
        z[j] = guide.at(mx[rect.x0 + u], my[rect.y0 + v]);
        state[j] = CellState::known;
      } else {
        any_unknown = true;
      }
    }
  if (!any_unknown) return;
  thin_plate_with_roughness(FieldView{w, h, z.data(), state.data(), farthest}, grid.origin_x() + rect.x0,
                            grid.origin_y() + rect.y0, params, ThinPlateSchedule{}, progress);
  for (int v = 0; v < h; ++v)
    std::copy_n(z.begin() + static_cast<std::ptrdiff_t>(v) * w, w,
                grid.elevations().begin() + static_cast<std::ptrdiff_t>(grid.index(rect.x0, rect.y0 + v)));
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
  const bool cropped = guided && params.method == Method::mcmd;
  const WindowRect rect = cropped ? solved_rect(layout, in, ox, oy, side) : WindowRect{0, 0, side, side};
  std::vector<double> dist;  // to the nearest known cell of the window
  double farthest = -1.0;    // a bound on it over rect, when known
  if (cropped && max_distance <= 0) {
    // Scattered samples: every cell near data, so no cell is pinned to the
    // guide and the transform is spared.
    const double radius = guide_radius(layout, *guide);
    farthest = near_bound(known, side, rect, std::min(radius, ThinPlateSchedule{}.shallow_reach));
  }
  if ((guided || max_distance > 0) && farthest < 0) dist = distance_to_valid(known.data(), side, side);
  if (guided) {
    const double pinned_farthest = pin_to_guide(grid, dist, guide_radius(layout, *guide), rect, mx, my, *guide);
    if (!dist.empty()) farthest = pinned_farthest;
  }
  morph::place_line_cells(grid, lines);
  if (cropped)
    fill_solved_rect(grid, rect, mx, my, *guide, params, farthest, progress);
  else if (grid.count(CellState::unknown) > 0)
    fill_grid(grid, params, progress);

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
