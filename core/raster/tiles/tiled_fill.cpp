#include "raster/tiles/tiled_fill.hpp"

#include <algorithm>
#include <numeric>
#include <stdexcept>

#include "mcmd/fill_raster.hpp"
#include "raster/tiles/tile_jobs.hpp"
#include "raster/tiles/tile_plan.hpp"

namespace mcmd::detail {

namespace {

// The order in which jobs are computed: the job list's, or the test hook's
// permutation of it.
std::vector<std::size_t> job_order(std::size_t n, const RasterFillHooks& hooks) {
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), std::size_t{0});
  if (!hooks.reorder) return order;
  hooks.reorder(order);
  std::vector<std::size_t> check = order;
  std::sort(check.begin(), check.end());
  for (std::size_t i = 0; i < n; ++i)
    if (check.size() != n || check[i] != i) throw std::invalid_argument("reorder hook must return a permutation");
  return order;
}

// Jobs read ahead of the next one to blend, per worker. Results are blended
// in job order, so with fewer one slow window (a large void) leaves the other
// workers idle once they have solved the jobs after it: with threads + 1 in
// flight, the 4801² blob mosaic's workers were busy 79 % and 68 % of the
// jobs' time; with 4 per thread, 86 % and 84 %. Each holds at most a window's
// input and result (~6 MB at T = 513).
constexpr std::size_t kJobsInFlightPerThread = 4;

struct PublishOnExit {
  const RasterFillHooks& hooks;
  const RasterFillStats& stats;
  ~PublishOnExit() {
    if (hooks.stats) *hooks.stats = stats;
  }
};

}  // namespace

void tiled_fill(const RasterAccess& raster, const FillParams& params, const TilingParams& tiling,
                const ProgressFn& progress, const RasterFillHooks& hooks, const LeftVoids& left) {
  RasterFillStats stats;
  const PublishOnExit publish{hooks, stats};  // the counts reach the caller even when this throws
  report(progress, 0.0);
  TilePlan plan;
  if (!plan_tiles(raster, params, tiling, sub_progress(progress, 0.0, 0.15), stats, plan, left)) {
    report(progress, 1.0);
    return;
  }
  const std::vector<std::size_t> order = job_order(plan.jobs.size(), hooks);
  const int threads = effective_threads(tiling.threads);
  // With a reordered run every job may be in flight: results are combined in job order.
  const std::size_t in_flight =
      hooks.reorder ? plan.jobs.size() : static_cast<std::size_t>(threads) * kJobsInFlightPerThread;
  run_tile_jobs(raster, plan, order, in_flight, threads, tiling.max_distance, sub_progress(progress, 0.15, 1.0),
                stats);
}

}  // namespace mcmd::detail
