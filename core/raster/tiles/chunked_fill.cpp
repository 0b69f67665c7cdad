// The tiled fill in chunks (mcmd/chunked_fill.hpp): the same plan, windows,
// small components and blending as tiles/tiled_fill.cpp, each step limited
// to one chunk's share.
#include "mcmd/chunked_fill.hpp"

#include <algorithm>
#include <memory>
#include <stdexcept>
#include <tuple>

#include "common/zero_runs.hpp"
#include "mcmd/fill_raster.hpp"
#include "raster/frame.hpp"
#include "raster/void_selection.hpp"
#include "raster/tiles/blend.hpp"
#include "raster/tiles/lone_void.hpp"
#include "raster/tiles/tile_jobs.hpp"
#include "raster/tiles/tile_plan.hpp"
#include "raster/tiles/tile_scan.hpp"
#include "raster/void_components.hpp"

namespace mcmd {

struct ChunkedPlan::State {
  detail::TilePlan plan;
  RasterFillStats stats;
  bool voids = false;
  double max_distance = 0.0;
  detail::LeftVoids left;  // -inner, -maxvoid
  std::vector<std::pair<int, int>> component_centres;  // of their grids: who solves each
};

namespace {

// Moments travel as 9 doubles.
void to_doubles(const CoarseGuide::Moments& m, double* d) {
  const double v[9] = {m.n, m.z, m.x, m.y, m.xx, m.yy, m.xy, m.zx, m.zy};
  std::copy_n(v, 9, d);
}
CoarseGuide::Moments from_doubles(const double* d) {
  return CoarseGuide::Moments{d[0], d[1], d[2], d[3], d[4], d[5], d[6], d[7], d[8]};
}

TileLayout layout_of(int width, int height, const TilingParams& tiling, Method method) {
  return TileLayout(width, height, effective_tile_side(width, height, tiling.tile_side, method));
}

bool inside(int x, int y, const CellRect& r) { return x >= r.x0 && x < r.x0 + r.w && y >= r.y0 && y < r.y0 + r.h; }

// Cells of a rectangle, read at once.
struct Cells {
  CellRect rect;
  std::vector<double> z;
  std::vector<std::uint8_t> valid;
};

// The known cells and void runs of rows [y0, y1) of `own`, from `c` (which holds them).
void count_rows(const Cells& c, const CellRect& own, int y0, int y1, ChunkSummary& s) {
  for (int y = y0; y < y1; ++y) {
    const std::size_t at = static_cast<std::size_t>(y - c.rect.y0) * c.rect.w + (own.x0 - c.rect.x0);
    const std::uint8_t* valid = c.valid.data() + at;
    const std::size_t known = detail::add_known_range(c.z.data() + at, valid, own.w, s.lo, s.hi);
    s.known += known;
    if (known == static_cast<std::size_t>(own.w)) continue;
    detail::for_each_zero_run(valid, own.w, [&](int x0, int x1) {
      s.voids += static_cast<std::size_t>(x1 - x0);
      s.void_runs.insert(s.void_runs.end(), {y, own.x0 + x0, own.x0 + x1});
    });
  }
}

// A summary reads its rows a strip at a time (a few MB, reused, rather than
// the chunk and its margin as doubles at once). A strip holds whole lattice
// rows of the guide's blocks, so each block's cells are summed in one pass
// in raster order, as the CLI's scan sums them.
struct SummaryStrip {
  int y0 = 0, y1 = 0;
  Range js{0, 0};  // the lattice rows whose blocks it holds
};
constexpr int kStripRows = 128;

std::vector<SummaryStrip> summary_strips(const CellRect& own, int height, int stride, Range js) {
  std::vector<SummaryStrip> strips;
  const auto plain = [&strips](int from, int to) {
    for (int y = from; y < to; y += kStripRows) strips.push_back(SummaryStrip{y, std::min(to, y + kStripRows), {0, 0}});
  };
  const int top = own.y0, bottom = own.y0 + own.h;
  if (js.size() <= 0) {
    plain(top, bottom);
    return strips;
  }
  const int half = stride / 2;
  const auto edge = [&](int j) { return std::clamp(j * stride - half, 0, height); };
  const int ya = edge(js.begin), yb = edge(js.end);
  plain(std::min(top, ya), ya);
  const int group = std::max(1, kStripRows / stride);
  for (int j = js.begin; j < js.end; j += group) {
    const int je = std::min(js.end, j + group);
    strips.push_back(SummaryStrip{edge(j), edge(je), Range{j, je}});
  }
  plain(yb, std::max(bottom, yb));
  return strips;
}

void put_moments(CoarseGuide& guide, const ChunkSummary& s) {
  const Range is{s.i0, s.i1}, js{s.j0, s.j1};
  std::vector<CoarseGuide::Moments> part(static_cast<std::size_t>(is.size()) * js.size());
  if (s.moments.size() != part.size() * 9) throw std::invalid_argument("a chunk summary's moments do not fit it");
  for (std::size_t k = 0; k < part.size(); ++k) part[k] = from_doubles(s.moments.data() + 9 * k);
  guide.set_moments(is, js, part);
}

// `out`, whose write touches only the part of a rectangle inside `own` (its
// buffers kept from one write to the next).
RasterAccess clipped(const RasterAccess& out, const CellRect& own) {
  RasterAccess a = out;
  struct Buffers {
    std::vector<double> z;
    std::vector<std::uint8_t> mask;
  };
  a.write = [&out, own, b = std::make_shared<Buffers>()](int x0, int y0, int w, int h, const double* z,
                                                         const std::uint8_t* mask) {
    const int cx0 = std::max(x0, own.x0), cy0 = std::max(y0, own.y0);
    const int cx1 = std::min(x0 + w, own.x0 + own.w), cy1 = std::min(y0 + h, own.y0 + own.h);
    if (cx0 >= cx1 || cy0 >= cy1) return;
    const int cw = cx1 - cx0, ch = cy1 - cy0;
    b->z.resize(static_cast<std::size_t>(cw) * ch);
    b->mask.resize(b->z.size());
    bool any = false;
    for (int y = 0; y < ch; ++y)
      for (int x = 0; x < cw; ++x) {
        const std::size_t from = static_cast<std::size_t>(cy0 - y0 + y) * w + (cx0 - x0 + x);
        b->z[static_cast<std::size_t>(y) * cw + x] = z[from];
        b->mask[static_cast<std::size_t>(y) * cw + x] = mask[from];
        any = any || mask[from];
      }
    if (any) out.write(cx0, cy0, cw, ch, b->z.data(), b->mask.data());
  };
  return a;
}

// A window's result kept at the region's void cells only: runs of void cells
// with the same write flag.
WindowSolution compact(const WindowResult& w, const WindowInput& in) {
  WindowSolution s{w.tx, w.ty, w.xs.begin, w.xs.end, w.ys.begin, w.ys.end, {}, {}};
  const int n = w.xs.size();
  for (int y = w.ys.begin; y < w.ys.end; ++y) {
    const std::size_t row = static_cast<std::size_t>(y - w.ys.begin) * n;
    const std::uint8_t* valid = in.valid.data() + static_cast<std::size_t>(y - in.rect.y0) * in.rect.w +
                                (w.xs.begin - in.rect.x0);
    detail::for_each_zero_run(valid, n, [&](int a, int b) {
      for (int x = a; x < b;) {
        const std::uint8_t writes = w.write[row + x] ? 1 : 0;
        const int start = x;
        while (x < b && (w.write[row + x] ? 1 : 0) == writes) ++x;
        s.runs.insert(s.runs.end(), {y, w.xs.begin + start, w.xs.begin + x, writes});
        s.z.insert(s.z.end(), w.z.begin() + static_cast<std::ptrdiff_t>(row + start),
                   w.z.begin() + static_cast<std::ptrdiff_t>(row + x));
      }
    });
  }
  return s;
}

// The window's result back over its whole region (0 at known cells), into
// `r` (its buffers reused from window to window). Throws std::invalid_argument
// for a solution that does not fit its region (it may have crossed a network).
void expand(const WindowSolution& s, WindowResult& r) {
  r.tx = s.tx, r.ty = s.ty;
  r.xs = Range{s.x0, s.x1}, r.ys = Range{s.y0, s.y1};
  const int w = r.xs.size(), h = r.ys.size();
  if (w < 0 || h < 0 || s.runs.size() % 4 != 0) throw std::invalid_argument("a window's solution does not fit it");
  r.z.assign(static_cast<std::size_t>(w) * h, 0.0);
  r.write.assign(r.z.size(), 0);
  std::size_t k = 0;
  for (std::size_t q = 0; q < s.runs.size(); q += 4) {
    const int y = s.runs[q], a = s.runs[q + 1], b = s.runs[q + 2];
    if (y < s.y0 || y >= s.y1 || a < s.x0 || b > s.x1 || a > b || s.z.size() - k < static_cast<std::size_t>(b - a))
      throw std::invalid_argument("a window's solution does not fit it");
    const std::size_t at = static_cast<std::size_t>(y - s.y0) * w + (a - s.x0);
    std::copy_n(s.z.begin() + static_cast<std::ptrdiff_t>(k), b - a, r.z.begin() + static_cast<std::ptrdiff_t>(at));
    if (s.runs[q + 3]) std::fill_n(r.write.begin() + static_cast<std::ptrdiff_t>(at), b - a, std::uint8_t{1});
    k += static_cast<std::size_t>(b - a);
  }
}

}  // namespace

ChunkGrid chunk_grid(int width, int height, const TilingParams& tiling, Method method) {
  const TileLayout layout = layout_of(width, height, tiling, method);
  ChunkGrid g;
  g.step = layout.x.step();
  g.whole = layout.tile_count() == 1;
  g.guide_stride = g.whole ? 0 : guide_stride(width, height);
  // Reads of the windows and lone voids a chunk solves; the guide's blocks.
  const int reach = std::max(window_reach(layout, method),
                             method == Method::mcmd ? detail::small_grid_reach(layout) : 0);
  g.margin = std::max(reach + 2, g.guide_stride / 2);
  g.min_side = g.margin;
  return g;
}

ChunkSummary summarize_chunk(const RasterAccess& raster, const TilingParams& tiling, Method method, CellRect own) {
  const int W = raster.width, H = raster.height;
  if (own.w < 1 || own.h < 1 || own.x0 < 0 || own.y0 < 0 || own.x0 + own.w > W || own.y0 + own.h > H)
    throw std::invalid_argument("the chunk does not lie inside the raster");
  const ChunkGrid grid = chunk_grid(W, H, tiling, method);
  const int stride = grid.guide_stride;
  ChunkSummary s;
  s.own = own;
  Range is{0, 0}, js{0, 0};
  int x0 = own.x0, x1 = own.x0 + own.w;  // the columns read: own's and its lattice blocks'
  if (!grid.whole) {
    is = CoarseGuide::lattice_points(W, stride, own.x0, own.x0 + own.w);
    js = CoarseGuide::lattice_points(H, stride, own.y0, own.y0 + own.h);
    if (is.size() > 0 && js.size() > 0) {
      x0 = std::min(x0, std::max(0, is.begin * stride - stride / 2));
      x1 = std::max(x1, std::min(W, is.end * stride - stride / 2));
    }
    s.i0 = is.begin, s.i1 = is.end, s.j0 = js.begin, s.j1 = js.end;
    s.moments.reserve(static_cast<std::size_t>(std::max(0, is.size())) * std::max(0, js.size()) * 9);
  }
  Cells cells;
  for (const SummaryStrip& strip : summary_strips(own, H, stride, is.size() > 0 ? js : Range{0, 0})) {
    cells.rect = CellRect{x0, strip.y0, x1 - x0, strip.y1 - strip.y0};
    const std::size_t n = static_cast<std::size_t>(cells.rect.w) * cells.rect.h;
    cells.z.resize(n);
    cells.valid.resize(n);
    if (n > 0)  // a lattice row past the raster's last cell has an empty block (zero moments)
      raster.read(cells.rect.x0, cells.rect.y0, cells.rect.w, cells.rect.h, cells.z.data(), cells.valid.data());
    count_rows(cells, own, std::max(strip.y0, own.y0), std::min(strip.y1, own.y0 + own.h), s);
    if (strip.js.size() <= 0) continue;
    const CoarseGuide::CellBlock block{cells.rect.x0, cells.rect.y0, cells.rect.w, cells.rect.h, cells.z.data(),
                                       cells.valid.data()};
    for (const CoarseGuide::Moments& m : CoarseGuide::part_moments(W, H, stride, is, strip.js, block)) {
      s.moments.resize(s.moments.size() + 9);
      to_doubles(m, s.moments.data() + s.moments.size() - 9);
    }
  }
  return s;
}

ChunkedPlan::ChunkedPlan(int width, int height, const FillParams& params, const TilingParams& tiling,
                         const std::vector<ChunkSummary>& summaries)
    : state_(std::make_unique<State>()) {
  detail::PlanParts parts;
  parts.width = width;
  parts.height = height;
  parts.lo = std::numeric_limits<double>::infinity();
  parts.hi = -parts.lo;
  std::vector<detail::VoidRun> runs;
  for (const ChunkSummary& s : summaries) {
    parts.lo = std::min(parts.lo, s.lo);
    parts.hi = std::max(parts.hi, s.hi);
    for (std::size_t k = 0; k + 2 < s.void_runs.size(); k += 3)
      runs.push_back(detail::VoidRun{s.void_runs[k], s.void_runs[k + 1], s.void_runs[k + 2]});
  }
  parts.voids = detail::RunsByRow(std::move(runs), height);
  parts.set_guide = [&summaries](CoarseGuide& guide) {
    for (const ChunkSummary& s : summaries) put_moments(guide, s);
  };
  State& st = *state_;
  st.max_distance = tiling.max_distance;
  try {
    st.voids = detail::plan_from_parts(parts, params, tiling, st.stats, st.plan, st.left);
  } catch (const detail::ExtremeRange&) {
    throw std::invalid_argument("known values beyond ±1e100 need the file's fill (a chunked fill has no frame)");
  }
  for (const detail::SmallComponent& c : st.plan.small) {
    const detail::ComponentGrid g = detail::component_grid(c.box, width, height);
    st.component_centres.emplace_back(g.rect.x0 + g.rect.w / 2, g.rect.y0 + g.rect.h / 2);
  }
}

ChunkedPlan::~ChunkedPlan() = default;

bool ChunkedPlan::has_voids() const { return state_->voids; }
std::size_t ChunkedPlan::known_cells() const { return state_->stats.known_cells; }
std::size_t ChunkedPlan::void_cells() const { return state_->stats.void_cells; }

ChunkSolution solve_chunk(const RasterAccess& raster, const ChunkedPlan& plan, CellRect own,
                          const ProgressFn& progress) {
  const ChunkedPlan::State& st = plan.state();
  const detail::TilePlan& tp = st.plan;
  ChunkSolution out;
  if (!st.voids) return out;
  const int P = tp.layout.x.step(), nx = tp.layout.x.count();
  detail::JobInput in;  // its buffers serve every job of the chunk
  for (const detail::Job& job : tp.jobs) {
    if (job.component) {
      const auto [cx, cy] = st.component_centres[job.index];
      if (!inside(cx, cy, own)) continue;
    } else {
      const int tx = static_cast<int>(job.index % nx), ty = static_cast<int>(job.index / nx);
      if (!inside(tx * P, ty * P, own)) continue;
    }
    report(progress, 0.0);
    detail::read_input(raster, tp, job, in);
    detail::JobResult r = detail::solve_job(raster, tp, job, in, st.max_distance, progress);
    if (job.component) {
      const detail::Box& b = tp.small[job.index].box;
      out.components.push_back(ComponentSolution{job.index, b.x0, b.y0, b.x1, b.y1, std::move(r.values)});
    } else {
      out.windows.push_back(compact(r.window, in.window));
    }
  }
  return out;
}

ChunkSolution solution_part(const ChunkSolution& s, CellRect other) {
  const auto meets = [&other](int x0, int x1, int y0, int y1) {  // [x0, x1) × [y0, y1)
    return x0 < other.x0 + other.w && x1 > other.x0 && y0 < other.y0 + other.h && y1 > other.y0;
  };
  ChunkSolution part;
  for (const WindowSolution& w : s.windows)
    if (meets(w.x0, w.x1, w.y0, w.y1)) part.windows.push_back(w);
  for (const ComponentSolution& c : s.components)
    if (meets(c.x0, c.x1 + 1, c.y0, c.y1 + 1)) part.components.push_back(c);
  return part;
}

void blend_chunk(const RasterAccess& out, const ChunkedPlan& plan, const std::vector<const ChunkSolution*>& around,
                 CellRect own) {
  const ChunkedPlan::State& st = plan.state();
  if (!st.voids) return;
  const detail::TilePlan& tp = st.plan;
  const RasterAccess selected = st.left.empty() ? out : detail::without_left_voids(out, st.left);
  const RasterAccess chunk = clipped(selected, own);
  // The windows whose output region meets the chunk, in the tiled fill's
  // order (row-major), each once.
  std::vector<const WindowSolution*> windows;
  for (const ChunkSolution* s : around)
    for (const WindowSolution& w : s->windows)
      if (w.x0 < own.x0 + own.w && w.x1 > own.x0 && w.y0 < own.y0 + own.h && w.y1 > own.y0) windows.push_back(&w);
  std::sort(windows.begin(), windows.end(),
            [](const WindowSolution* a, const WindowSolution* b) { return std::tie(a->ty, a->tx) < std::tie(b->ty, b->tx); });
  windows.erase(std::unique(windows.begin(), windows.end(),
                            [](const WindowSolution* a, const WindowSolution* b) { return a->tx == b->tx && a->ty == b->ty; }),
                windows.end());
  const int P = tp.layout.x.step();
  Blender blender(tp.layout, chunk.write, Range{own.x0 - P, own.x0 + own.w + P});
  int rows_ended = 0;
  WindowResult result;
  for (const WindowSolution* w : windows) {
    for (; rows_ended < w->ty; ++rows_ended) blender.end_row(rows_ended);
    expand(*w, result);
    blender.add(result);
  }
  for (; rows_ended < tp.layout.y.count(); ++rows_ended) blender.end_row(rows_ended);

  // Small components: one value per cell, written as they are.
  std::vector<bool> done(tp.small.size(), false);
  for (const ChunkSolution* s : around)
    for (const ComponentSolution& c : s->components) {
      if (c.index >= tp.small.size() || done[c.index]) continue;
      done[c.index] = true;
      const detail::SmallComponent& comp = tp.small[c.index];
      if (c.values.size() != detail::cell_count(comp.runs))
        throw std::invalid_argument("a small void's solution does not fit it");
      detail::write_component(chunk, comp, c.values);
    }
}

}  // namespace mcmd
