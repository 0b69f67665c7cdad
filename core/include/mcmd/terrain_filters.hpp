// What mcmd_terrain does around a synthesis: supersampling a coarse DEM
// (its cells become constraints of a finer grid), the median post-filter of
// the paper's material example (Belhadj 2007 Fig. 13), and the hillshade of
// the preview.
#pragma once

#include <cstdint>
#include <vector>

#include "mcmd/terrain.hpp"

namespace mcmd {

// The canvas of a coarse w×h raster supersampled by an integer factor k: a
// ((w−1)k+1)×((h−1)k+1) grid whose cell (k·i, k·j) is coarse cell (i, j)
// (known where `valid`), every other cell unknown. Cell centres coincide, so
// the fine grid's origin is the coarse one's shifted by (k−1)/(2k) coarse
// cells. Throws std::invalid_argument for k < 1 or a result too large.
Canvas upsampled(const std::vector<double>& z, const std::vector<std::uint8_t>& valid, int w, int h, int k);

// `passes` passes of a size×size median filter (size odd, >= 3; the window
// shrinks at the borders). Only unknown cells change unless `all_cells`.
// The same bits for any thread count.
void median_filter(Canvas& canvas, int size, int passes, bool all_cells, int threads = 1);

// Shaded relief in [1, 255] (0 is left for nodata), Horn's gradient, light
// from azimuth 315°, altitude 45°; dx, dy the cell size in elevation units.
std::vector<std::uint8_t> hillshade(const std::vector<double>& z, int w, int h, double dx, double dy);

}  // namespace mcmd
