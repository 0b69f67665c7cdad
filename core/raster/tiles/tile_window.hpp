// One tile's window: what to read for it, and its fill (docs/tiling.md).
//
// The paper methods (and a raster of one tile) solve the whole window, a
// 2^n+1 grid (n = layout.window_levels()) whose cell (u, v) is raster cell
// (ox + u, oy + v), reflected into the raster where it falls outside. The
// default method on several tiles reads a *region window*, the tile's output
// region grown by the guide radius and 2 cells, and solves only the region
// grown by one blend band. With a coarse guide, unknown cells farther than
// guide_radius from every known cell of the window, and unknown cells on the
// outer 2-cell ring of what is solved, are pinned to it, so every solve is
// constrained, deep void interiors are the same in every window, and windows
// only solve the fine detail near known cells. The result is the fill over
// the tile's output region.
#pragma once

#include <cstdint>
#include <vector>

#include "common/grid.hpp"
#include "mcmd/params.hpp"
#include "mcmd/progress.hpp"
#include "morphology/lines.hpp"
#include "raster/coarse_guide.hpp"
#include "raster/tiles/blend.hpp"
#include "raster/tiles/tile_layout.hpp"
#include "raster/void_components.hpp"

namespace mcmd {

// The raster cells a window needs: [x0, x0+w) × [y0, y0+h), inside the raster.
struct ReadRect {
  int x0 = 0, y0 = 0, w = 0, h = 0;
};
ReadRect window_read_rect(const TileLayout& layout, int tx, int ty, Method method);

// True when tile windows of `method` are region windows (above).
bool solves_region(const TileLayout& layout, Method method);

// How far beyond its tile's cells a tile's window reads.
int window_reach(const TileLayout& layout, Method method);

// The guide radius never exceeds this many cells: what it is at T = 129,
// where the halo bounds it, and what blob voids measured best at larger tiles
// (docs/tiling.md).
constexpr double kGuideRadiusCap = 46.0;

// Unknown cells farther than this (cells, Euclidean) from every known cell of
// a window are pinned to the guide: min(8 · stride, P/2 - b - 2,
// kGuideRadiusCap), at least 1.
double guide_radius(const TileLayout& layout, const CoarseGuide& guide);

// The conjugate gradients of a window, or of a small void solved alone, stop
// at a relative residual of 3e-2, not the 1e-2 of a void solved whole: their
// outer ring and deep cells are pinned to the guide, so what is left to
// converge is the detail near data. With the soft coarse pins
// (multigrid.hpp) this costs what 5e-2 cost with the stiffer ones (4801²
// blob mosaic, one thread: 1.58 against 1.64 s of CPU, RMSE 122.50 against
// 123.86 m), and two windows agree on their overlap to 0.16 instead of 0.5 m
// (TiledFill.VoidAcrossASeamIsOneSurface; docs/tiling.md, Layout).
constexpr double kPinnedPcgTolerance = 3e-2;

struct WindowInput {
  int tx = 0;
  int ty = 0;
  ReadRect rect;
  std::vector<double> z;            // rect.w × rect.h
  std::vector<std::uint8_t> valid;  // 1 = known
};

// Up to this max distance the window sees every known cell that decides
// whether a cell of its output region is written: min(P/2 - b, kGuideRadiusCap + 2).
int exact_distance_limit(const TileLayout& layout);

// Fill tile (tx, ty)'s window. `guide` may be null (a single-tile layout,
// where the window holds the whole raster, mirrored). A cell is flagged for
// writing when it is void and, with max_distance > 0, within max_distance
// cells (Euclidean) of a known cell: exact when max_distance <=
// exact_distance_limit (or for a single tile); beyond, a cell with no known
// cell within max_distance in the window is decided by the guide's
// coarse_distance (prepare_distance() must have been called).
// Throws Cancelled (from progress), std::invalid_argument (no constraint).
// Line cells (morphology/lines.hpp; may be empty) become ridge and river cells.
// Cells of `solved_alone` (small voids, solved on their own; may be null) are
// not written, and a region window solves only around the cells it writes.
WindowResult solve_window(const TileLayout& layout, const WindowInput& in, const CoarseGuide* guide,
                          const FillParams& params, double max_distance, const ProgressFn& progress = {},
                          const std::vector<morph::LineCell>& lines = {},
                          const detail::RunsByRow* solved_alone = nullptr);

}  // namespace mcmd
