// The raster engine's entry point: checks the request and chooses the path,
// the raster held whole (whole_raster.hpp) or streamed through tiles
// (tiles/tiled_fill.hpp).
#include "mcmd/fill_raster.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <thread>

#include "raster/frame.hpp"
#include "raster/tiles/tile_layout.hpp"
#include "raster/tiles/tiled_fill.hpp"
#include "raster/void_selection.hpp"
#include "raster/whole_raster.hpp"

namespace mcmd {

int effective_tile_side(int width, int height, int requested, Method method) {
  if (requested != 0 && !is_tile_side(requested))
    throw std::invalid_argument("tile size must be 2^k + 1 (3, 5, 9, ..., 257, 513, 1025, ...)");
  const int side = requested == 0 ? default_tile_side(method) : requested;
  int cover = 3;  // smallest 2^k + 1 >= max(width, height), k >= 1
  while (cover < std::max(width, height) && cover < side) cover = 2 * (cover - 1) + 1;
  return std::min(side, cover);
}

int effective_threads(int requested) {
  if (requested > 0) return requested;
  const unsigned hw = std::thread::hardware_concurrency();
  return hw > 0 ? static_cast<int>(hw) : 1;
}

bool fills_whole(int width, int height, const FillParams& params, const TilingParams& tiling) {
  const std::size_t cells = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
  return params.method == Method::mcmd && !tiling.always_tile && cells <= detail::kWholeRasterMaxCells;
}

namespace {

void check_inputs(const RasterAccess& raster, const TilingParams& tiling) {
  if (raster.width < 1 || raster.height < 1) throw std::invalid_argument("raster size must be at least 1×1");
  if (!raster.read || !raster.write) throw std::invalid_argument("raster access needs read and write functions");
  if (!std::isfinite(tiling.max_distance) || tiling.max_distance < 0)
    throw std::invalid_argument("max distance must be a finite number >= 0");
  if (tiling.threads < 0) throw std::invalid_argument("thread count must be >= 0");
  effective_tile_side(raster.width, raster.height, tiling.tile_side, Method::mcmd);  // throws on a bad size
}

}  // namespace

namespace {

void fill_by_path(const RasterAccess& raster, const FillParams& params, const TilingParams& tiling,
                  const ProgressFn& progress, const RasterFillHooks& hooks, const detail::LeftVoids& left) {
  if (fills_whole(raster.width, raster.height, params, tiling))
    detail::fill_whole_raster(raster, params, tiling, progress, hooks, left);
  else
    detail::tiled_fill(raster, params, tiling, progress, hooks, left);
}

}  // namespace

void fill_raster(const RasterAccess& raster, const FillParams& params, const TilingParams& tiling,
                 const ProgressFn& progress, const RasterFillHooks& hooks) {
  check_inputs(raster, tiling);
  // The voids to leave unfilled are judged whole, before any tile is filled.
  const detail::LeftVoids left =
      detail::selects_voids(tiling) ? detail::find_left_voids(raster, tiling) : detail::LeftVoids{};
  const RasterAccess selected = left.empty() ? raster : detail::without_left_voids(raster, left);
  try {
    fill_by_path(selected, params, tiling, progress, hooks, left);
  } catch (const detail::ExtremeRange& e) {  // nothing written yet: again, in a frame (raster/frame.hpp)
    const detail::Frame frame = detail::frame_for(e.lo, e.hi);
    fill_by_path(detail::framed(selected, frame), detail::framed(params, frame), tiling, progress, hooks, left);
  }
}

}  // namespace mcmd
