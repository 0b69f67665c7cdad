// Pass 1 of the tiled fill (internal): one streaming read of the raster.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "mcmd/progress.hpp"
#include "mcmd/raster_access.hpp"
#include "raster/coarse_guide.hpp"
#include "raster/tiles/tile_layout.hpp"
#include "raster/void_components.hpp"
#include "raster/void_selection.hpp"

namespace mcmd::detail {

struct ScanResult {
  std::size_t known = 0;
  std::size_t voids = 0;
  double lo = 0.0;  // known elevation range (lo > hi when no cell is known)
  double hi = -1.0;
  std::vector<std::uint8_t> needs;  // per tile, row-major: a void lies in its output region
  // Likewise, a void cell that is not left (raster/void_selection.hpp);
  // empty when no void is left.
  std::vector<std::uint8_t> needs_filled;
};

// The known cells of a row of n cells: their count, and lo and hi widened
// to their range.
std::size_t add_known_range(const double* z, const std::uint8_t* valid, int n, double& lo, double& hi);

// Read the raster in full-width row blocks of about a million cells, count
// known and void cells, feed `guide` and `components` (either may be null),
// mark the tiles to solve. With threads > 1 the guide is fed on a thread of
// its own.
ScanResult scan_raster(const RasterAccess& raster, const TileLayout& layout, CoarseGuide* guide,
                       const ProgressFn& progress, ComponentFinder* components = nullptr,
                       const LeftVoids* left = nullptr, int threads = 1);

// scan_raster's result (but lo and hi) for a raster whose voids are `voids`,
// from the runs alone: a plan built from chunks (plan_from_parts).
ScanResult scan_void_runs(const RunsByRow& voids, const TileLayout& layout, ComponentFinder* components,
                          const LeftVoids* left);

}  // namespace mcmd::detail
