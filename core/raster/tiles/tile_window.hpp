// One tile's window: what to read for it, and its fill (docs/tiling.md).
//
// The window of tile (tx, ty) is a 2^n+1 grid (n = layout.window_levels())
// whose cell (u, v) is raster cell (ox + u, oy + v), reflected into the raster
// where it falls outside. With a coarse guide, unknown cells on the outer
// 2-cell ring and unknown cells farther than guide_radius from every known
// cell are pinned to it, so every window is constrained, deep void interiors
// are the same in every window, and windows only solve the fine detail near
// known cells. The result is the fill over the tile's output region.
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

namespace mcmd {

// The raster cells a window needs: [x0, x0+w) × [y0, y0+h), inside the raster.
struct ReadRect {
  int x0 = 0, y0 = 0, w = 0, h = 0;
};
ReadRect window_read_rect(const TileLayout& layout, int tx, int ty);

// Unknown cells farther than this (cells, Euclidean) from every known cell of
// a window are pinned to the guide: min(8 · stride, P/2 - b - 2), at least 1.
double guide_radius(const TileLayout& layout, const CoarseGuide& guide);

struct WindowInput {
  int tx = 0;
  int ty = 0;
  ReadRect rect;
  std::vector<double> z;            // rect.w × rect.h
  std::vector<std::uint8_t> valid;  // 1 = known
};

// Up to this max distance the window sees every known cell that decides
// whether a cell of its output region is written: P/2 - b.
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
WindowResult solve_window(const TileLayout& layout, const WindowInput& in, const CoarseGuide* guide,
                          const FillParams& params, double max_distance, const ProgressFn& progress = {},
                          const std::vector<morph::LineCell>& lines = {});

}  // namespace mcmd
