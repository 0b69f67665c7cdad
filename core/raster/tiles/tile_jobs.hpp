// The tiled fill's job pipeline (internal to tiles/tiled_fill.cpp): the
// calling thread reads each job's input, a worker pool solves jobs, and the
// calling thread takes the results in job order, writing a small component's
// cells as they are and blending windows across the seams (blend.hpp).
// read/write/progress stay on the calling thread.
#pragma once

#include <cstddef>
#include <memory>
#include <vector>

#include "mcmd/progress.hpp"
#include "mcmd/raster_access.hpp"
#include "raster/tiles/lone_void.hpp"
#include "raster/tiles/tile_plan.hpp"

namespace mcmd::detail {

// A job's input: the rectangle it reads and its cells (a component's grid,
// or with -morph auto its void field, too).
struct JobInput {
  WindowInput window;
  ComponentGrid grid;  // a component's
  Box field;           // a component's void field, with -morph auto (window.rect)
};

struct JobResult {
  WindowResult window;         // a window's
  std::vector<double> values;  // a component's cells, run after run
};

// Read a job's input (raster.read, on the calling thread).
std::shared_ptr<JobInput> read_input(const RasterAccess& raster, const TilePlan& plan, const Job& job);
// The same into `in`, whose buffers are reused (a caller reading jobs one by one).
void read_input(const RasterAccess& raster, const TilePlan& plan, const Job& job, JobInput& in);

// Solve a job (any thread): a window's fill with the small components'
// cells taken off its writes, or a component's values.
JobResult solve_job(const RasterAccess& raster, const TilePlan& plan, const Job& job, const JobInput& in,
                    double max_distance, const ProgressFn& progress);

// Write a small component's values (its cells, run after run) as they are:
// one value per cell, whoever asks, never blended. Returns the cells written.
std::size_t write_component(const RasterAccess& raster, const SmallComponent& c, const std::vector<double>& values);

// Run plan.jobs, computed in `order` (a permutation of the job indices; a
// reordered run still combines results in job order), at most `in_flight`
// jobs read but not yet written (bounds memory to a few windows per thread).
// Counts written cells into stats. Throws Cancelled, rethrows a job's error.
void run_tile_jobs(const RasterAccess& raster, const TilePlan& plan, const std::vector<std::size_t>& order,
                   std::size_t in_flight, int threads, double max_distance, const ProgressFn& progress,
                   RasterFillStats& stats);

}  // namespace mcmd::detail
