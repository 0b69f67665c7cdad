// Which voids a fill leaves alone (-inner, -maxvoid): a void is a set of void
// cells connected through their 8 neighbours, as a user sees it on a map.
// With inner_only, a void with a cell on the raster's border (the sea, the
// outside of a survey footprint) is left; with max_cells > 0, a void of more
// cells than that is left. Found in one streaming pass over the rows, so a
// void crossing any number of tiles is judged as one.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "mcmd/raster_access.hpp"
#include "raster/void_components.hpp"

namespace mcmd::detail {

// Whether `tiling` asks to leave some voids unfilled.
inline bool selects_voids(const TilingParams& tiling) { return tiling.inner_only || tiling.max_void_cells > 0; }

// The cells of the voids left unfilled.
using LeftVoids = RunsByRow;

// Streaming 8-connected labelling of the void cells. Memory: one record per
// void run of the raster (a few bytes per run).
class VoidSelector {
 public:
  VoidSelector(int width, int height, const TilingParams& tiling);
  // Row y (rows in order 0, 1, 2, ...): valid[x] != 0 for known cells.
  void add_row(int y, const std::uint8_t* valid);
  // After the last row: the voids left unfilled.
  LeftVoids finish();

 private:
  int find(int i);
  void unite(int a, int b);

  int width_, height_;
  bool inner_only_;
  std::size_t max_cells_;
  std::vector<VoidRun> runs_;
  std::vector<int> parent_;
  std::vector<std::size_t> cells_;    // per root: the void's cells
  std::vector<std::uint8_t> border_;  // per root: whether it touches the raster's border
  std::size_t prev_begin_ = 0, prev_end_ = 0;  // the previous row's runs
};

// The voids `tiling` leaves, read from `raster` in strips of full rows.
LeftVoids find_left_voids(const RasterAccess& raster, const TilingParams& tiling);

// `raster`, whose write never touches a left cell.
RasterAccess without_left_voids(const RasterAccess& raster, const LeftVoids& left);

}  // namespace mcmd::detail
