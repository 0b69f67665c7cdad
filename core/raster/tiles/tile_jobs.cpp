#include "raster/tiles/tile_jobs.hpp"

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <exception>
#include <memory>
#include <mutex>
#include <optional>

#include "common/worker_pool.hpp"
#include "raster/tiles/blend.hpp"
#include "raster/tiles/lone_void.hpp"

namespace mcmd::detail {

namespace {

// Results of jobs in flight, indexed by their position in the job list.
struct Mailbox {
  std::mutex mutex;
  std::condition_variable ready;
  std::vector<std::optional<JobResult>> results;
  std::vector<std::exception_ptr> errors;

  explicit Mailbox(std::size_t n) : results(n), errors(n) {}
  void put(std::size_t pos, JobResult r) {
    {
      std::lock_guard<std::mutex> lock(mutex);
      results[pos] = std::move(r);
    }
    ready.notify_all();
  }
  void fail(std::size_t pos, std::exception_ptr e) {
    {
      std::lock_guard<std::mutex> lock(mutex);
      errors[pos] = std::move(e);
    }
    ready.notify_all();
  }
  // The result at `pos` once ready, waiting at most 100 ms (false: not yet).
  // Rethrows the job's error.
  bool take(std::size_t pos, JobResult& out) {
    std::unique_lock<std::mutex> lock(mutex);
    ready.wait_for(lock, std::chrono::milliseconds(100), [&] { return results[pos].has_value() || errors[pos]; });
    if (errors[pos]) std::rethrow_exception(errors[pos]);
    if (!results[pos]) return false;
    out = std::move(*results[pos]);
    results[pos].reset();
    return true;
  }
};

// Sets the flag when leaving scope, so workers stop early on any exit.
struct CancelOnExit {
  std::atomic<bool>& flag;
  ~CancelOnExit() { flag = true; }
};

// With -morph auto a small component is read and solved in its void field.
bool in_field(const TilePlan& plan, const Job& job) { return job.component && plan.params.morph.channels; }

}  // namespace

std::shared_ptr<JobInput> read_input(const RasterAccess& raster, const TilePlan& plan, const Job& job) {
  auto in = std::make_shared<JobInput>();
  read_input(raster, plan, job, *in);
  return in;
}

void read_input(const RasterAccess& raster, const TilePlan& plan, const Job& job, JobInput& in) {
  in.window.tx = in.window.ty = 0;
  in.grid = ComponentGrid{};
  in.field = Box{};
  if (in_field(plan, job)) {
    in.field = void_field_rect(plan.small[job.index].box, raster.width, raster.height);
    in.window.rect = ReadRect{in.field.x0, in.field.y0, in.field.width(), in.field.height()};
  } else if (job.component) {
    in.grid = component_grid(plan.small[job.index].box, raster.width, raster.height);
    in.window.rect = in.grid.rect;
  } else {
    const int nx = plan.layout.x.count();
    in.window.tx = static_cast<int>(job.index % nx);
    in.window.ty = static_cast<int>(job.index / nx);
    in.window.rect = window_read_rect(plan.layout, in.window.tx, in.window.ty, plan.params.method);
  }
  const ReadRect& r = in.window.rect;
  const std::size_t cells = static_cast<std::size_t>(r.w) * r.h;
  in.window.z.resize(cells);
  in.window.valid.resize(cells);
  raster.read(r.x0, r.y0, r.w, r.h, in.window.z.data(), in.window.valid.data());
}

JobResult solve_job(const RasterAccess& raster, const TilePlan& plan, const Job& job, const JobInput& in,
                    double max_distance, const ProgressFn& progress) {
  JobResult r;
  if (in_field(plan, job)) {
    r.values = solve_component_in_field(plan.small[job.index], in.field, in.window.z, in.window.valid.data(),
                                        plan.guide, plan.params, progress, plan.lines);
  } else if (job.component) {
    r.values = solve_component(plan.small[job.index], in.grid, raster.width, raster.height, in.window.z.data(),
                               in.window.valid.data(), plan.guide, plan.radius, plan.params, progress, plan.lines);
  } else {
    r.window = solve_window(plan.layout, in.window, plan.guide_or_null(), plan.params, max_distance, progress,
                            plan.lines, &plan.small_runs);
  }
  return r;
}

std::size_t write_component(const RasterAccess& raster, const SmallComponent& c, const std::vector<double>& values) {
  const int w = c.box.width(), h = c.box.height();
  std::vector<double> z(static_cast<std::size_t>(w) * h, 0.0);
  std::vector<std::uint8_t> mask(z.size(), 0);
  std::size_t k = 0;
  for (const VoidRun& run : c.runs)
    for (int x = run.x0; x < run.x1; ++x, ++k) {
      const std::size_t i = static_cast<std::size_t>(run.y - c.box.y0) * w + (x - c.box.x0);
      z[i] = values[k];
      mask[i] = 1;
    }
  raster.write(c.box.x0, c.box.y0, w, h, z.data(), mask.data());
  return k;
}

void run_tile_jobs(const RasterAccess& raster, const TilePlan& plan, const std::vector<std::size_t>& order,
                   std::size_t in_flight, int threads, double max_distance, const ProgressFn& progress,
                   RasterFillStats& stats) {
  const std::size_t N = plan.jobs.size();
  Blender blender(plan.layout, [&](int x0, int y0, int w, int h, const double* z, const std::uint8_t* mask) {
    raster.write(x0, y0, w, h, z, mask);
    for (std::size_t i = 0; i < static_cast<std::size_t>(w) * h; ++i) stats.cells_written += mask[i] ? 1 : 0;
  });
  Mailbox box(N);
  std::atomic<bool> cancel{false};
  const ProgressFn worker_progress = [&cancel](double) { return !cancel.load(std::memory_order_relaxed); };
  WorkerPool pool(threads);
  CancelOnExit stop_workers{cancel};  // destroyed first: workers see it before the pool joins

  std::size_t next_submit = 0;
  int rows_ended = 0;
  for (std::size_t next = 0; next < N; ++next) {
    for (; next_submit < N && next_submit - next < in_flight; ++next_submit) {
      const std::size_t pos = order[next_submit];
      std::shared_ptr<const JobInput> in = read_input(raster, plan, plan.jobs[pos]);
      pool.submit([&, pos, in] {
        try {
          box.put(pos, solve_job(raster, plan, plan.jobs[pos], *in, max_distance, worker_progress));
        } catch (...) {
          box.fail(pos, std::current_exception());
        }
      });
    }
    JobResult r;
    while (!box.take(next, r)) report(progress, static_cast<double>(next) / N);  // lets a cancel through
    // Report before writing: a refusal here leaves this window unwritten
    // (a raster of one tile is then left untouched).
    report(progress, static_cast<double>(next + 1) / N);
    const Job& job = plan.jobs[next];
    if (job.component) {
      stats.cells_written += write_component(raster, plan.small[job.index], r.values);
    } else {
      for (; rows_ended < r.window.ty; ++rows_ended) blender.end_row(rows_ended);
      blender.add(r.window);
    }
  }
  for (; rows_ended < plan.layout.y.count(); ++rows_ended) blender.end_row(rows_ended);
}

}  // namespace mcmd::detail
