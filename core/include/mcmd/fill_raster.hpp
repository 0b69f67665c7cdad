// The raster engine's entry point: fill the voids of a raster of any size,
// held whole when it is small, else streamed through 2^k+1 tiles with bounded
// memory, seamless output and bit-identical results for any thread count or
// processing order (SPEC §3; the design is in docs/tiling.md).
#pragma once

#include "mcmd/params.hpp"
#include "mcmd/progress.hpp"
#include "mcmd/raster_access.hpp"

namespace mcmd {

// Whether fill_raster reads this raster whole once and writes it at the end
// (raster/whole_raster.hpp) instead of streaming it through tiles: the default
// method on a raster of at most 2^21 cells (e.g. 1448²), tiles not forced.
// (It may still hand the raster, read once, to the tiles: a void that reaches
// far from data.)
bool fills_whole(int width, int height, const FillParams& params, const TilingParams& tiling);

// Fill every void cell of the raster (every void cell within max_distance of
// a known cell when max_distance > 0); known cells are never written.
// Throws std::invalid_argument (bad parameters, no known cell), Cancelled when
// `progress` refuses (from the calling thread only), and rethrows what
// read/write throw.
void fill_raster(const RasterAccess& raster, const FillParams& params, const TilingParams& tiling,
                 const ProgressFn& progress = {}, const RasterFillHooks& hooks = {});

// The tile side actually used: `requested` (0 = default_tile_side(method)),
// reduced to the smallest 2^k + 1 (k >= 1) that covers max(width, height)
// when that is smaller. Throws std::invalid_argument when requested is
// neither 0 nor 2^k + 1.
int effective_tile_side(int width, int height, int requested, Method method);

// Worker threads actually used for `requested` (0 = hardware concurrency).
int effective_threads(int requested);

}  // namespace mcmd
