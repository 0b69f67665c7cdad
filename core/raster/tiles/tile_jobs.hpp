// The tiled fill's job pipeline (internal to tiles/tiled_fill.cpp): the
// calling thread reads each job's input, a worker pool solves jobs, and the
// calling thread takes the results in job order, writing a small component's
// cells as they are and blending windows across the seams (blend.hpp).
// read/write/progress stay on the calling thread.
#pragma once

#include <cstddef>
#include <vector>

#include "mcmd/progress.hpp"
#include "mcmd/raster_access.hpp"
#include "raster/tiles/tile_plan.hpp"

namespace mcmd::detail {

// Run plan.jobs, computed in `order` (a permutation of the job indices; a
// reordered run still combines results in job order), at most `in_flight`
// jobs read but not yet written (bounds memory to a few windows per thread).
// Counts written cells into stats. Throws Cancelled, rethrows a job's error.
void run_tile_jobs(const RasterAccess& raster, const TilePlan& plan, const std::vector<std::size_t>& order,
                   std::size_t in_flight, int threads, double max_distance, const ProgressFn& progress,
                   RasterFillStats& stats);

}  // namespace mcmd::detail
