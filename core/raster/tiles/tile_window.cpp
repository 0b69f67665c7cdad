#include "raster/tiles/tile_window.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <stdexcept>

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

// Raster cells [x0, x0 + w) × [y0, y0 + h) a window covers (outside the
// raster, mirrored in).
struct WindowSpan {
  int x0 = 0, y0 = 0, w = 0, h = 0;
};

// How far a region window reaches beyond its output region: the guide radius
// and the pins' 2-cell margin, never past the 2^n+1 window.
int region_margin(const TileLayout& layout) {
  return std::min(static_cast<int>(kGuideRadiusCap) + 2, layout.x.step() / 2 - layout.x.band() + 1);
}

WindowSpan window_span(const TileLayout& layout, int tx, int ty, Method method) {
  if (solves_region(layout, method)) {
    const Range rx = layout.x.region(tx), ry = layout.y.region(ty);
    const int m = region_margin(layout);
    return WindowSpan{rx.begin - m, ry.begin - m, rx.size() + 2 * m, ry.size() + 2 * m};
  }
  return WindowSpan{layout.x.window_origin(tx), layout.y.window_origin(ty), layout.x.window_side(),
                    layout.y.window_side()};
}

// A window's cells, read from its input (mirrored where outside the raster).
struct WindowCells {
  WindowSpan span;
  std::vector<int> mx, my;  // raster column of each window column, row of each row
  std::vector<double> z;
  std::vector<CellState> state;
  std::vector<std::uint8_t> known;  // known in the raster (not pins)
  std::size_t index(int u, int v) const { return static_cast<std::size_t>(v) * span.w + u; }
};

// The cells of `span` (part of the window, or all of it).
WindowCells load_window(const TileLayout& layout, const WindowInput& in, const WindowSpan& span) {
  WindowCells c;
  c.span = span;
  c.mx = reflected(c.span.x0, c.span.w, layout.x.length());
  c.my = reflected(c.span.y0, c.span.h, layout.y.length());
  const std::size_t cells = static_cast<std::size_t>(c.span.w) * c.span.h;
  c.z.resize(cells);
  c.state.resize(cells);
  c.known.resize(cells);
  const std::size_t rw = static_cast<std::size_t>(in.rect.w);
  for (int v = 0; v < c.span.h; ++v) {
    const std::size_t row = static_cast<std::size_t>(c.my[v] - in.rect.y0) * rw;
    const std::size_t i = c.index(0, v);
    for (int u = 0; u < c.span.w; ++u) {
      const std::size_t src = row + static_cast<std::size_t>(c.mx[u] - in.rect.x0);
      const bool known = in.valid[src] != 0;
      c.z[i + u] = known ? in.z[src] : 0.0;
      c.state[i + u] = known ? CellState::known : CellState::unknown;
      c.known[i + u] = known;
    }
  }
  return c;
}

// [x0, x1) × [y0, y1) in window cells.
struct WindowRect {
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  int w() const { return x1 - x0; }
  int h() const { return y1 - y0; }
};

// What the default method solves of a region window: the tile's output
// region grown by `context` cells (one blend band, unless the window is
// shallow: below) on every side. Every cell the blend takes from the window
// then has that much context, and no cell is solved twice beyond the bands.
// The paper methods subdivide the whole 2^n+1 window.
WindowRect solved_rect(const TileLayout& layout, const WindowInput& in, const WindowSpan& span, int context) {
  const Range rx = layout.x.region(in.tx), ry = layout.y.region(in.ty);
  return WindowRect{std::max(0, rx.begin - span.x0 - context), std::max(0, ry.begin - span.y0 - context),
                    std::min(span.w, rx.end - span.x0 + context), std::min(span.h, ry.end - span.y0 + context)};
}

// The context of a shallow window, one whose every cell lies near data
// (scattered samples): there the thin plate is local, and 4 cells measured
// the same RMSE and seam curvature as a band of 16 on the 4801² 3.3 %-kept
// mosaic, for 8 % less time on one thread (1 cell: +0.08 % RMSE).
constexpr int kShallowContext = 4;

// Where a region window's solve may start and end: on multiples of this
// (raster coordinates), so that the solver's coarse lattices fall on the same
// cells whatever the voids' extent. Unsnapped, the 4801² blobs moved by ±0.7 %
// in RMSE with the margin; snapped, by 0.05 %.
constexpr int kFocusSnap = 32;

int snap_down(int v) { return (v >= 0 ? v : v - (kFocusSnap - 1)) / kFocusSnap * kFocusSnap; }
int snap_up(int v) { return -snap_down(-v); }

// The bounding box (raster cells) of the output region's cells that the
// window writes (`write`: 1 there; small voids are solved alone, not by the
// window); x1 < x0 when it writes none.
detail::Box written_box(const TileLayout& layout, const WindowInput& in, const std::vector<std::uint8_t>& write) {
  const Range rx = layout.x.region(in.tx), ry = layout.y.region(in.ty);
  detail::Box b{rx.end, ry.end, rx.begin - 1, ry.begin - 1};
  std::size_t k = 0;
  for (int y = ry.begin; y < ry.end; ++y)
    for (int x = rx.begin; x < rx.end; ++x, ++k)
      if (write[k]) {
        b.x0 = std::min(b.x0, x), b.x1 = std::max(b.x1, x);
        b.y0 = std::min(b.y0, y), b.y1 = std::max(b.y1, y);
      }
  return b;
}

// What a region window needs to solve: the cells it writes (`written`),
// grown by one blend band and snapped, within `rect`, so that every written
// cell keeps a band of context. A window that a large void only grazes then
// solves the part it fills, not its whole region. Empty when nothing is
// written.
WindowRect focus(const WindowSpan& span, const TileLayout& layout, const detail::Box& written, const WindowRect& rect) {
  if (written.x1 < written.x0) return WindowRect{};
  const int bx = layout.x.band(), by = layout.y.band();
  return WindowRect{std::max(rect.x0, snap_down(written.x0 - bx) - span.x0),
                    std::max(rect.y0, snap_down(written.y0 - by) - span.y0),
                    std::min(rect.x1, snap_up(written.x1 + bx + 1) - span.x0),
                    std::min(rect.y1, snap_up(written.y1 + by + 1) - span.y0)};
}

// The part of `full` within `by` cells of `rect` (window cells of `full`).
WindowSpan around(const WindowSpan& full, const WindowRect& rect, int by) {
  const int x0 = std::max(0, rect.x0 - by), y0 = std::max(0, rect.y0 - by);
  const int x1 = std::min(full.w, rect.x1 + by), y1 = std::min(full.h, rect.y1 + by);
  return WindowSpan{full.x0 + x0, full.y0 + y0, x1 - x0, y1 - y0};
}

// `rect`, in window cells of `full`, in those of its part `part`.
WindowRect shifted(const WindowRect& rect, const WindowSpan& full, const WindowSpan& part) {
  const int dx = part.x0 - full.x0, dy = part.y0 - full.y0;
  return WindowRect{rect.x0 - dx, rect.y0 - dy, rect.x1 - dx, rect.y1 - dy};
}

// The output region's void cells (read from the input: the region lies in
// the raster), less those of `alone` (may be null).
std::vector<std::uint8_t> voids_to_write(const TileLayout& layout, const WindowInput& in,
                                         const detail::RunsByRow* alone) {
  const Range rx = layout.x.region(in.tx), ry = layout.y.region(in.ty);
  std::vector<std::uint8_t> write(static_cast<std::size_t>(rx.size()) * ry.size());
  std::size_t k = 0;
  for (int y = ry.begin; y < ry.end; ++y) {
    const std::uint8_t* valid =
        in.valid.data() + static_cast<std::size_t>(y - in.rect.y0) * in.rect.w + (rx.begin - in.rect.x0);
    for (int x = 0; x < rx.size(); ++x, ++k) write[k] = valid[x] ? 0 : 1;
  }
  if (alone) alone->clear(rx.begin, ry.begin, rx.size(), ry.size(), write.data());
  return write;
}

// The distance to the window's known cells, exact up to `reach` inside
// `rect` (distance_to_valid_near): a window that a large void grazes pays the
// transform for what it solves, not its whole area (over whole windows the
// transform took 6 % of the 4801² blob mosaic's CPU time).
PartDistance distance_near(const WindowCells& c, const WindowRect& rect, double reach) {
  return distance_to_valid_near(c.known.data(), c.span.w, c.span.h, rect.x0, rect.y0, rect.x1, rect.y1, reach);
}

// A bound on every cell's distance to a known cell inside `rect`, when all
// lie within `reach` (Euclidean) by a Chebyshev test; -1 otherwise.
double near_bound(const WindowCells& c, const WindowRect& rect, double reach) {
  const int r = static_cast<int>(std::floor(reach / std::sqrt(2.0)));
  if (r < 1) return -1.0;
  std::vector<std::uint8_t> sub(static_cast<std::size_t>(rect.w()) * rect.h());
  for (int v = 0; v < rect.h(); ++v)
    std::copy_n(c.known.begin() + static_cast<std::ptrdiff_t>(c.index(rect.x0, rect.y0 + v)), rect.w(),
                sub.begin() + static_cast<std::ptrdiff_t>(v) * rect.w());
  return all_within_chebyshev(sub.data(), rect.w(), rect.h(), r) ? r * std::sqrt(2.0) : -1.0;
}

// Pins unknown cells of `solved` (the part of the window solved) to the
// guide: with `dist` (the distance to the window's known cells; empty when no
// cell is that far), those farther than `radius`, since deep inside voids the
// guide is the surface; then the unknown cells of its outer 2-cell ring, so
// that the solve is constrained. Returns the largest distance left unpinned.
double pin_to_guide(WindowCells& c, const PartDistance& dist, double radius, const WindowRect& solved,
                    const CoarseGuide& guide) {
  const auto pin = [&](int u, int v) {
    const std::size_t i = c.index(u, v);
    c.z[i] = guide.at(c.mx[u], c.my[v]);
    c.state[i] = CellState::known;
  };
  double farthest = 0.0;
  if (!dist.empty())
    for (int v = solved.y0; v < solved.y1; ++v)
      for (int u = solved.x0; u < solved.x1; ++u) {
        const double d = dist.at(u, v);
        if (d > radius) pin(u, v);
        else farthest = std::max(farthest, d);
      }
  for (int v = solved.y0; v < solved.y1; ++v) {
    const bool ring_row = v < solved.y0 + 2 || v >= solved.y1 - 2;
    const int skip_to = std::max(solved.x0 + 2, solved.x1 - 2);  // past the inside of a row
    for (int u = solved.x0; u < solved.x1; u = ring_row || u != solved.x0 + 1 ? u + 1 : skip_to)
      if (c.state[c.index(u, v)] == CellState::unknown) pin(u, v);
  }
  return farthest;
}

// The default method on `rect` of the window, in place.
void fill_rect(WindowCells& c, const WindowRect& rect, const FillParams& params, double farthest,
               const ProgressFn& progress) {
  const int w = rect.w(), h = rect.h();
  std::vector<double> z(static_cast<std::size_t>(w) * h);
  std::vector<CellState> state(z.size());
  for (int v = 0; v < h; ++v) {
    const std::ptrdiff_t from = static_cast<std::ptrdiff_t>(c.index(rect.x0, rect.y0 + v)), to = std::ptrdiff_t{v} * w;
    std::copy_n(c.z.begin() + from, w, z.begin() + to);
    std::copy_n(c.state.begin() + from, w, state.begin() + to);
  }
  if (std::none_of(state.begin(), state.end(), [](CellState s) { return s == CellState::unknown; })) return;
  ThinPlateSchedule schedule;
  schedule.pcg_tol = kPinnedPcgTolerance;
  thin_plate_with_roughness(FieldView{w, h, z.data(), state.data(), farthest}, c.span.x0 + rect.x0,
                            c.span.y0 + rect.y0, params, schedule, progress);
  for (int v = 0; v < h; ++v)
    std::copy_n(z.begin() + std::ptrdiff_t{v} * w, w,
                c.z.begin() + static_cast<std::ptrdiff_t>(c.index(rect.x0, rect.y0 + v)));
}

// The whole 2^n+1 window through fill_grid (the paper methods; a single tile).
void fill_whole(WindowCells& c, const TileLayout& layout, const FillParams& params, const ProgressFn& progress) {
  if (std::none_of(c.state.begin(), c.state.end(), [](CellState s) { return s == CellState::unknown; })) return;
  Grid grid(layout.window_levels(), c.span.x0, c.span.y0);
  std::copy(c.z.begin(), c.z.end(), grid.elevations().begin());
  std::copy(c.state.begin(), c.state.end(), grid.states().begin());
  fill_grid(grid, params, progress);
  std::copy(grid.elevations().begin(), grid.elevations().end(), c.z.begin());
}

}  // namespace

bool solves_region(const TileLayout& layout, Method method) {
  return method == Method::mcmd && layout.tile_count() > 1;
}

int window_reach(const TileLayout& layout, Method method) {
  return solves_region(layout, method) ? layout.x.band() - 1 + region_margin(layout) : layout.x.step() / 2;
}

double guide_radius(const TileLayout& layout, const CoarseGuide& guide) {
  // 8 guide strides (measured: 4 and 16 were worse on blob voids), at most
  // kGuideRadiusCap, kept inside the halo so every window that outputs a cell
  // sees the same known cells within that radius.
  const double limit = std::min<double>(kGuideRadiusCap, layout.x.step() / 2 - layout.x.band() - 2);
  return std::max(1.0, std::min(kGuideRadiusStrides * guide.stride(), limit));
}

int exact_distance_limit(const TileLayout& layout) {
  const int halo = std::min(layout.x.step(), layout.y.step()) / 2 - layout.x.band();
  return std::min(halo, static_cast<int>(kGuideRadiusCap) + 2);
}

ReadRect window_read_rect(const TileLayout& layout, int tx, int ty, Method method) {
  // Reflection maps a run of cells onto a run, so [min, max] covers them all.
  const WindowSpan s = window_span(layout, tx, ty, method);
  const std::vector<int> xs = reflected(s.x0, s.w, layout.x.length());
  const std::vector<int> ys = reflected(s.y0, s.h, layout.y.length());
  const auto [x0, x1] = std::minmax_element(xs.begin(), xs.end());
  const auto [y0, y1] = std::minmax_element(ys.begin(), ys.end());
  return ReadRect{*x0, *y0, *x1 - *x0 + 1, *y1 - *y0 + 1};
}

WindowResult solve_window(const TileLayout& layout, const WindowInput& in, const CoarseGuide* guide,
                          const FillParams& params, double max_distance, const ProgressFn& progress,
                          const std::vector<morph::LineCell>& lines, const detail::RunsByRow* solved_alone) {
  const bool region = solves_region(layout, params.method);
  const bool guided = guide && guide->ready();
  if (region && !guided) throw std::logic_error("a tiled window of the default method needs the guide");
  const WindowSpan full = window_span(layout, in.tx, in.ty, params.method);
  std::vector<std::uint8_t> write = voids_to_write(layout, in, solved_alone);
  const detail::Box written = written_box(layout, in, write);
  const int band = layout.x.band();
  const WindowRect whole{0, 0, full.w, full.h};
  WindowRect rect = region ? focus(full, layout, written, solved_rect(layout, in, full, band)) : whole;
  const double radius = guided ? guide_radius(layout, *guide) : 0.0;
  const bool idle = region && (rect.w() <= 0 || rect.h() <= 0);  // nothing to write
  // Loaded: with -md (the written cells' distances over the whole window)
  // or a whole-window solve all of it; else what is solved and the cells
  // within the guide radius of it, all that its distances see (on the 4801²
  // blob mosaic a third of the window).
  WindowSpan span = full;
  if (idle)
    span = WindowSpan{full.x0, full.y0, 0, 0};
  else if (region && max_distance <= 0)
    span = around(full, rect, near_margin(radius));
  WindowCells c = load_window(layout, in, span);
  rect = shifted(rect, full, span);

  PartDistance dist;  // to the nearest known cell of the window
  if (!idle) {
    double farthest = -1.0;  // a bound on dist over rect
    // Scattered samples: every cell near data, so none is pinned to the guide
    // and the transform is spared.
    if (region && max_distance <= 0)
      farthest = near_bound(c, rect, std::min(radius, ThinPlateSchedule{}.shallow_reach));
    if (farthest >= 0)  // shallow: less context (the bound holds on the smaller rect)
      rect = shifted(focus(full, layout, written, solved_rect(layout, in, full, std::min(band, kShallowContext))), full,
                     span);
    // Exact over the whole window with -md (the written cells' distances
    // decide what is written); else only the guide radius matters.
    if ((guided || max_distance > 0) && farthest < 0)
      dist = max_distance > 0 ? distance_near(c, whole, std::max(c.span.w, c.span.h)) : distance_near(c, rect, radius);
    if (guided) {
      const double unpinned = pin_to_guide(c, dist, radius, rect, *guide);
      if (!dist.empty()) farthest = unpinned;
    }
    morph::place_line_cells(c.span.w, c.span.h, c.span.x0, c.span.y0, c.z.data(), c.state.data(), lines);
    if (region)
      fill_rect(c, rect, params, farthest, progress);
    else
      fill_whole(c, layout, params, progress);
  }

  WindowResult r;
  r.tx = in.tx;
  r.ty = in.ty;
  r.xs = layout.x.region(in.tx);
  r.ys = layout.y.region(in.ty);
  const std::size_t cells = static_cast<std::size_t>(r.xs.size()) * r.ys.size();
  r.z.resize(cells);
  r.write = std::move(write);
  const bool beyond_window = guided && max_distance > exact_distance_limit(layout);
  // Every cell this window writes lies in what it solved, so inside what it
  // loaded; the others are 0 (the blend uses a window's cells where it writes).
  const int xa = std::max(r.xs.begin, c.span.x0), xb = std::min(r.xs.end, c.span.x0 + c.span.w);
  for (int y = std::max(r.ys.begin, c.span.y0); y < std::min(r.ys.end, c.span.y0 + c.span.h); ++y)
    if (xa < xb)
      std::copy_n(c.z.begin() + static_cast<std::ptrdiff_t>(c.index(xa - c.span.x0, y - c.span.y0)), xb - xa,
                  r.z.begin() + static_cast<std::ptrdiff_t>(y - r.ys.begin) * r.xs.size() + (xa - r.xs.begin));
  if (max_distance <= 0) return r;
  std::size_t k = 0;
  for (int y = r.ys.begin; y < r.ys.end; ++y)
    for (int x = r.xs.begin; x < r.xs.end; ++x, ++k)
      // Beyond what the window sees, the guide's coarse distance decides.
      if (r.write[k] && !within_fill_distance(dist.at(x - c.span.x0, y - c.span.y0), max_distance))
        r.write[k] = beyond_window && within_fill_distance(guide->coarse_distance(x, y), max_distance) ? 1 : 0;
  return r;
}

}  // namespace mcmd
