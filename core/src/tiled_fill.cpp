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
}

// Results of windows in flight, indexed by their position in row-major order.
struct Mailbox {
  std::mutex mutex;
  std::condition_variable ready;
  std::vector<std::optional<WindowResult>> results;
  std::vector<std::exception_ptr> errors;
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
  const TileLayout layout(raster.width, raster.height,
                          effective_tile_side(raster.width, raster.height, tiling.tile_side));
  const bool single = layout.tile_count() == 1;
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
  const detail::ScanResult scan =
      detail::scan_raster(raster, layout, single ? nullptr : &guide, sub_progress(progress, 0.0, 0.10));
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
    guide.solve(p, sub_progress(progress, 0.10, 0.15));
    stats.guide_stride = guide.stride();
    if (tiling.max_distance > exact_distance_limit(layout)) guide.prepare_distance();
  }
  const CoarseGuide* guide_ptr = single ? nullptr : &guide;

  // Tiles to solve, row-major; `order` is the order windows are computed in.
  std::vector<std::size_t> tiles;
  for (std::size_t t = 0; t < scan.needs.size(); ++t)
    if (scan.needs[t]) tiles.push_back(t);
  const std::size_t N = tiles.size();
  stats.windows_solved = N;
  std::vector<std::size_t> order(N);
  std::iota(order.begin(), order.end(), std::size_t{0});
  if (hooks.reorder) {
    hooks.reorder(order);
    std::vector<std::size_t> check = order;
    std::sort(check.begin(), check.end());
    for (std::size_t i = 0; i < N; ++i)
      if (check.size() != N || check[i] != i) throw std::invalid_argument("reorder hook must return a permutation");
  }

  const int threads = effective_threads(tiling.threads);
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
        auto in = std::make_shared<WindowInput>();
        in->tx = static_cast<int>(tiles[pos] % nx);
        in->ty = static_cast<int>(tiles[pos] / nx);
        in->rect = window_read_rect(layout, in->tx, in->ty);
        const std::size_t cells = static_cast<std::size_t>(in->rect.w) * in->rect.h;
        in->z.resize(cells);
        in->valid.resize(cells);
        raster.read(in->rect.x0, in->rect.y0, in->rect.w, in->rect.h, in->z.data(), in->valid.data());
        pool.submit([&, pos, in] {
          try {
            WindowResult r = solve_window(layout, *in, guide_ptr, p, max_distance, worker_progress);
            std::lock_guard<std::mutex> lock(box.mutex);
            box.results[pos] = std::move(r);
          } catch (...) {
            std::lock_guard<std::mutex> lock(box.mutex);
            box.errors[pos] = std::current_exception();
          }
          box.ready.notify_all();
        });
      }
      WindowResult r;
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
      for (; rows_ended < r.ty; ++rows_ended) blender.end_row(rows_ended);
      blender.add(r);
      ++next_blend;
    }
    for (; rows_ended < layout.y.count(); ++rows_ended) blender.end_row(rows_ended);
  }
  publish();
}

}  // namespace mcmd
