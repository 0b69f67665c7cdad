// The tiled fill's driver (docs/tiling.md): pass 1 streams the raster once
// (counts, coarse-guide sums, which tiles hold voids), the guide is filled once,
// then the windows of the tiles with voids are solved by a worker pool while
// the calling thread reads their input, blends results in row-major tile order
// and writes what is final. read/write/progress stay on the calling thread.
#include "mcmd/tiled_fill.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <exception>
#include <memory>
#include <mutex>
#include <numeric>
#include <optional>
#include <stdexcept>
#include <thread>

#include "mcmd/blend.hpp"
#include "mcmd/coarse_guide.hpp"
#include "mcmd/tile_layout.hpp"
#include "mcmd/tile_window.hpp"
#include "single_field.hpp"
#include "small_void.hpp"
#include "tile_scan.hpp"
#include "worker_pool.hpp"

namespace mcmd {

int effective_tile_side(int width, int height, int requested) {
  if (requested != 0 && !is_tile_side(requested))
    throw std::invalid_argument("tile size must be 2^k + 1 (3, 5, 9, ..., 257, 513, 1025, ...)");
  const int side = requested == 0 ? kDefaultTileSide : requested;
  int cover = 3;  // smallest 2^k + 1 >= max(width, height), k >= 1
  while (cover < std::max(width, height) && cover < side) cover = 2 * (cover - 1) + 1;
  return std::min(side, cover);
}

int effective_threads(int requested) {
  if (requested > 0) return requested;
  const unsigned hw = std::thread::hardware_concurrency();
  return hw > 0 ? static_cast<int>(hw) : 1;
}

namespace {

void check_inputs(const RasterAccess& raster, const TilingParams& tiling) {
  if (raster.width < 1 || raster.height < 1) throw std::invalid_argument("raster size must be at least 1×1");
  if (!raster.read || !raster.write) throw std::invalid_argument("raster access needs read and write functions");
  if (!std::isfinite(tiling.max_distance) || tiling.max_distance < 0)
    throw std::invalid_argument("max distance must be a finite number >= 0");
  if (tiling.threads < 0) throw std::invalid_argument("thread count must be >= 0");
  effective_tile_side(raster.width, raster.height, tiling.tile_side);  // throws on a bad size, tiles or not
}

// A job: a small void component solved alone, or a tile's window.
struct Job {
  bool component = false;
  std::size_t index = 0;  // into the small components, or a tile (row-major)
};

struct JobResult {
  WindowResult window;         // a window's
  std::vector<double> values;  // a component's cells, run after run
};

// Results of jobs in flight, indexed by their position in the job list.
struct Mailbox {
  std::mutex mutex;
  std::condition_variable ready;
  std::vector<std::optional<JobResult>> results;
  std::vector<std::exception_ptr> errors;
};

// The runs of the small components, by row, to keep windows off their cells.
struct RunIndex {
  std::vector<detail::VoidRun> runs;  // sorted by (y, x0)
  std::vector<std::size_t> row_start;  // height + 1
  void build(const std::vector<detail::SmallComponent>& small, int height) {
    for (const auto& c : small) runs.insert(runs.end(), c.runs.begin(), c.runs.end());
    std::sort(runs.begin(), runs.end(), [](const detail::VoidRun& a, const detail::VoidRun& b) {
      return a.y != b.y ? a.y < b.y : a.x0 < b.x0;
    });
    row_start.assign(static_cast<std::size_t>(height) + 1, 0);
    for (const auto& r : runs) ++row_start[static_cast<std::size_t>(r.y) + 1];
    for (std::size_t y = 0; y < static_cast<std::size_t>(height); ++y) row_start[y + 1] += row_start[y];
  }
  // Clear the write flags of a window result on small components' cells.
  void mask(WindowResult& r) const {
    if (runs.empty()) return;
    const int rw = r.xs.size();
    for (int y = r.ys.begin; y < r.ys.end; ++y)
      for (std::size_t k = row_start[y]; k < row_start[y + 1]; ++k) {
        const int b = std::max(runs[k].x0, r.xs.begin), e = std::min(runs[k].x1, r.xs.end);
        for (int x = b; x < e; ++x) r.write[static_cast<std::size_t>(y - r.ys.begin) * rw + (x - r.xs.begin)] = 0;
      }
  }
};

// Sets the flag when leaving scope, so workers stop early on any exit.
struct CancelOnExit {
  std::atomic<bool>& flag;
  ~CancelOnExit() { flag = true; }
};

}  // namespace

void tiled_fill(const RasterAccess& raster, const FillParams& params, const TilingParams& tiling,
                const ProgressFn& progress) {
  tiled_fill(raster, params, tiling, progress, TiledFillHooks{});
}

void tiled_fill(const RasterAccess& raster, const FillParams& params, const TilingParams& tiling,
                const ProgressFn& progress, const TiledFillHooks& hooks) {
  check_inputs(raster, tiling);
  if (detail::single_field_applies(raster.width, raster.height, params, tiling) &&
      detail::fill_single_field(raster, params, tiling, sub_progress(progress, 0.0, 1.0), hooks.stats))
    return;
  const TileLayout layout(raster.width, raster.height,
                          effective_tile_side(raster.width, raster.height, tiling.tile_side));
  const bool single = layout.tile_count() == 1;
  const int threads = effective_threads(tiling.threads);
  CoarseGuide guide;
  if (!single) guide = CoarseGuide(raster.width, raster.height, guide_stride(raster.width, raster.height));
  TiledFillStats stats;
  stats.tile_side = layout.tile_side();
  stats.tiles_x = layout.x.count();
  stats.tiles_y = layout.y.count();
  auto publish = [&] {
    if (hooks.stats) *hooks.stats = stats;
  };

  report(progress, 0.0);
  // Small void components are solved alone (docs/tiling.md, "Small voids"):
  // the default method only, with a guide (several tiles), without -md.
  const int small_extent = detail::max_small_extent(layout);
  std::optional<detail::ComponentFinder> finder;
  if (!single && params.method == Method::mcmd && tiling.max_distance == 0 && small_extent >= 1)
    finder.emplace(raster.width, small_extent);
  detail::ScanResult scan = detail::scan_raster(raster, layout, single ? nullptr : &guide,
                                                sub_progress(progress, 0.0, 0.10), finder ? &*finder : nullptr);
  if (finder) {
    finder->finish();
    if (finder->overflow()) finder.reset();
  }
  stats.void_cells = scan.voids;
  stats.known_cells = scan.known;
  publish();
  if (scan.voids == 0) {
    publish();
    report(progress, 1.0);
    return;
  }
  if (scan.known == 0) throw std::invalid_argument("the raster has no known cell to fill from");

  // One noise unit for every window, so displacement amplitudes agree across seams.
  FillParams p = params;
  if (p.noise_unit <= 0) p.noise_unit = scan.hi - scan.lo;
  if (!single) {
    guide.solve(p, sub_progress(progress, 0.10, 0.15), threads);
    stats.guide_stride = guide.stride();
    if (tiling.max_distance > exact_distance_limit(layout)) guide.prepare_distance();
  }
  const CoarseGuide* guide_ptr = single ? nullptr : &guide;

  // Jobs: the small components (in order of their first cell), then the tiles
  // to solve, row-major; `order` is the order jobs are computed in.
  const bool components = finder && guide_ptr && guide_ptr->ready();
  std::vector<detail::SmallComponent> small;
  RunIndex small_runs;
  if (components) {
    small = std::move(finder->small());
    small_runs.build(small, raster.height);
    // Only tiles whose output region meets a large component's box need a window.
    std::fill(scan.needs.begin(), scan.needs.end(), 0);
    for (const detail::Box& b : finder->large())
      for (int ty = 0; ty < layout.y.count(); ++ty) {
        const Range ry = layout.y.region(ty);
        if (ry.end <= b.y0 || ry.begin > b.y1) continue;
        for (int tx = 0; tx < layout.x.count(); ++tx) {
          const Range rx = layout.x.region(tx);
          if (rx.end > b.x0 && rx.begin <= b.x1) scan.needs[static_cast<std::size_t>(ty) * layout.x.count() + tx] = 1;
        }
      }
  }
  finder.reset();
  std::vector<Job> jobs;
  for (std::size_t c = 0; c < small.size(); ++c) jobs.push_back(Job{true, c});
  for (std::size_t t = 0; t < scan.needs.size(); ++t)
    if (scan.needs[t]) jobs.push_back(Job{false, t});
  const std::size_t N = jobs.size();
  stats.windows_solved = N - small.size();
  stats.small_components = small.size();
  const double radius = guide_ptr && guide_ptr->ready() ? guide_radius(layout, *guide_ptr) : 0.0;
  std::vector<std::size_t> order(N);
  std::iota(order.begin(), order.end(), std::size_t{0});
  if (hooks.reorder) {
    hooks.reorder(order);
    std::vector<std::size_t> check = order;
    std::sort(check.begin(), check.end());
    for (std::size_t i = 0; i < N; ++i)
      if (check.size() != N || check[i] != i) throw std::invalid_argument("reorder hook must return a permutation");
  }

  // Windows read but not yet blended: bounds memory to a few windows per thread.
  const std::size_t limit = hooks.reorder ? N : static_cast<std::size_t>(threads) + 1;
  const int nx = layout.x.count();

  Blender blender(layout, [&](int x0, int y0, int w, int h, const double* z, const std::uint8_t* mask) {
    raster.write(x0, y0, w, h, z, mask);
    for (std::size_t i = 0; i < static_cast<std::size_t>(w) * h; ++i) stats.cells_written += mask[i] ? 1 : 0;
  });
  const ProgressFn window_progress = sub_progress(progress, 0.15, 1.0);

  Mailbox box;
  box.results.resize(N);
  box.errors.resize(N);
  std::atomic<bool> cancel{false};
  const ProgressFn worker_progress = [&cancel](double) { return !cancel.load(std::memory_order_relaxed); };
  const double max_distance = tiling.max_distance;
  {
    detail::WorkerPool pool(threads);
    CancelOnExit stop_workers{cancel};  // destroyed first: workers see it before the pool joins

    std::size_t next_submit = 0, next_blend = 0;
    int rows_ended = 0;
    while (next_blend < N) {
      while (next_submit < N && next_submit - next_blend < limit) {
        const std::size_t pos = order[next_submit++];
        const Job job = jobs[pos];
        auto in = std::make_shared<WindowInput>();
        detail::ComponentGrid cg;
        if (job.component) {
          cg = detail::component_grid(small[job.index].box, raster.width, raster.height);
          in->rect = cg.rect;
        } else {
          in->tx = static_cast<int>(job.index % nx);
          in->ty = static_cast<int>(job.index / nx);
          in->rect = window_read_rect(layout, in->tx, in->ty);
        }
        const std::size_t cells = static_cast<std::size_t>(in->rect.w) * in->rect.h;
        in->z.resize(cells);
        in->valid.resize(cells);
        raster.read(in->rect.x0, in->rect.y0, in->rect.w, in->rect.h, in->z.data(), in->valid.data());
        pool.submit([&, pos, in, job, cg] {
          try {
            JobResult r;
            if (job.component) {
              r.values = detail::solve_component(small[job.index], cg, raster.width, raster.height, in->z.data(),
                                                 in->valid.data(), *guide_ptr, radius, p, worker_progress);
            } else {
              r.window = solve_window(layout, *in, guide_ptr, p, max_distance, worker_progress);
              small_runs.mask(r.window);
            }
            std::lock_guard<std::mutex> lock(box.mutex);
            box.results[pos] = std::move(r);
          } catch (...) {
            std::lock_guard<std::mutex> lock(box.mutex);
            box.errors[pos] = std::current_exception();
          }
          box.ready.notify_all();
        });
      }
      JobResult r;
      for (bool got = false; !got;) {
        {
          std::unique_lock<std::mutex> lock(box.mutex);
          box.ready.wait_for(lock, std::chrono::milliseconds(100), [&] {
            return box.results[next_blend].has_value() || box.errors[next_blend];
          });
          if (box.errors[next_blend]) std::rethrow_exception(box.errors[next_blend]);
          if (box.results[next_blend]) {
            r = std::move(*box.results[next_blend]);
            box.results[next_blend].reset();
            got = true;
          }
        }
        if (!got) report(window_progress, static_cast<double>(next_blend) / N);  // lets a cancel through
      }
      // Report before writing: a refusal here leaves this window unwritten
      // (a raster of one tile is then left untouched).
      report(window_progress, static_cast<double>(next_blend + 1) / N);
      const Job& job = jobs[next_blend];
      if (job.component) {
        // One value per cell, whoever asks: written as is, never blended.
        const detail::SmallComponent& c = small[job.index];
        const int w = c.box.width(), h = c.box.height();
        std::vector<double> z(static_cast<std::size_t>(w) * h, 0.0);
        std::vector<std::uint8_t> mask(z.size(), 0);
        std::size_t k = 0;
        for (const detail::VoidRun& run : c.runs)
          for (int x = run.x0; x < run.x1; ++x, ++k) {
            const std::size_t i = static_cast<std::size_t>(run.y - c.box.y0) * w + (x - c.box.x0);
            z[i] = r.values[k];
            mask[i] = 1;
          }
        raster.write(c.box.x0, c.box.y0, w, h, z.data(), mask.data());
        stats.cells_written += k;
      } else {
        for (; rows_ended < r.window.ty; ++rows_ended) blender.end_row(rows_ended);
        blender.add(r.window);
      }
      ++next_blend;
    }
    for (; rows_ended < layout.y.count(); ++rows_ended) blender.end_row(rows_ended);
  }
  publish();
}

}  // namespace mcmd
