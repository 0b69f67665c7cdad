// What the tiled fill will do, decided by one streaming pass (internal to
// tiles/tiled_fill.cpp): the tile layout, the coarse guide, the small void
// components solved alone and the list of jobs.
#pragma once

#include <cstddef>
#include <functional>
#include <vector>

#include "mcmd/params.hpp"
#include "mcmd/progress.hpp"
#include "mcmd/raster_access.hpp"
#include "morphology/lines.hpp"
#include "raster/coarse_guide.hpp"
#include "raster/tiles/tile_layout.hpp"
#include "raster/tiles/tile_window.hpp"
#include "raster/void_components.hpp"
#include "raster/void_selection.hpp"

namespace mcmd::detail {

// A job: a small void component solved alone, or a tile's window.
struct Job {
  bool component = false;
  std::size_t index = 0;  // into TilePlan::small, or a tile (row-major)
};

struct TilePlan {
  TileLayout layout;
  bool single = false;  // one tile: its window holds the whole raster, no guide
  CoarseGuide guide;    // solved, unless single
  FillParams params;    // the caller's, with the raster's noise unit
  double radius = 0.0;  // guide radius (tile_window.hpp); 0 without a guide
  std::vector<SmallComponent> small;  // solved alone (lone_void.hpp)
  RunsByRow small_runs;  // their cells, kept off the windows' writes
  std::vector<morph::LineCell> lines;  // the raster's line cells in voids (morphology/lines.hpp)
  std::vector<Job> jobs;  // the small components in order of their first cell, then tiles row-major
  const CoarseGuide* guide_or_null() const { return single ? nullptr : &guide; }
};

// Pass 1 (counts, guide sums, components, tiles holding voids), then the
// guide's solve; progress over [0, 1]. Returns false when the raster has no
// void (nothing to do). Fills stats' counts. Throws std::invalid_argument
// when no cell is known, Cancelled.
bool plan_tiles(const RasterAccess& raster, const FillParams& params, const TilingParams& tiling,
                const ProgressFn& progress, RasterFillStats& stats, TilePlan& plan, const LeftVoids& left);

// What pass 1 gathers, brought together from the chunks of a fill split over
// workers (raster/tiles/chunked_fill.cpp): the void cells, the known range,
// and the guide's moments (set_guide puts them into a guide of the layout's
// size).
struct PlanParts {
  int width = 0;
  int height = 0;
  RunsByRow voids;
  double lo = 0.0;
  double hi = -1.0;
  std::function<void(CoarseGuide&)> set_guide;
};

// The plan plan_tiles makes of the raster these parts were gathered from
// (same guide, components and jobs; no lines), and the voids `tiling` leaves
// unfilled (found as fill_raster finds them). The raster must have a void and
// a known cell (else returns false / throws as plan_tiles).
bool plan_from_parts(const PlanParts& parts, const FillParams& params, const TilingParams& tiling,
                     RasterFillStats& stats, TilePlan& plan, LeftVoids& left);

}  // namespace mcmd::detail
