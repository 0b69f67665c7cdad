// Where the tiles of a large raster lie, which window solves each, and the
// partition-of-unity weights that blend neighbouring windows (docs/tiling.md).
//
// Along one axis of `length` cells, tile t covers cells [t·P, t·P + P] with
// P = T - 1 (T = 2^k + 1): neighbours share their border cell, like subtrees of
// the global subdivision. Tile t is solved in a window of side 2P + 1 starting
// at t·P - P/2 (the tile plus a halo of P/2 on each side; cells outside the
// raster are mirrored in). The seam s (between tiles s-1 and s) lies at s·P;
// cells with |x - s·P| < b are blended between the two windows with weights
// that sum to one, b = P/8 between 1 and kMaxBand ("band half-width"). Tile t's output region
// is the cells where its weight is > 0: [t·P - b + 1, (t+1)·P + b - 1].
#pragma once

#include <cstddef>

namespace mcmd {

// The blend band's half-width never exceeds this: what it is at T = 129. A
// band hides the windows' residual differences; wider ones at larger tiles
// only add cells solved twice (docs/tiling.md).
constexpr int kMaxBand = 16;

// C² smooth ramp: 0 for u <= 0, 1 for u >= 1, 6u⁵ - 15u⁴ + 10u³ between;
// ramp(u) + ramp(1 - u) = 1.
double blend_ramp(double u);

// [begin, end) along one axis; empty when begin >= end.
struct Range {
  int begin = 0;
  int end = 0;
  bool empty() const { return begin >= end; }
  int size() const { return end > begin ? end - begin : 0; }
};

class TileAxis {
 public:
  TileAxis() = default;
  // Pre: length >= 1, step = 2^k with k >= 1.
  TileAxis(int length, int step);

  int length() const { return length_; }
  int step() const { return step_; }    // P
  int count() const { return count_; }  // tiles
  int band() const { return band_; }    // b

  int window_origin(int t) const { return t * step_ - step_ / 2; }
  int window_side() const { return 2 * step_ + 1; }

  // Cells where tile t's weight is > 0, clipped to the raster.
  Range region(int t) const;
  // Cells blended only from tile t (weight exactly 1), clipped.
  Range solo(int t) const;
  // Cells of seam s (1 <= s < count) blended from tiles s-1 and s, clipped.
  Range seam_band(int s) const;
  // Weight of tile t at cell x: 1 in solo(t), a ramp across seam bands, 0 elsewhere.
  double weight(int t, int x) const;
  // The tile whose own cells [t·P, (t+1)·P) hold x (the last tile also holds its end).
  int owner(int x) const;

 private:
  int length_ = 1;
  int step_ = 2;
  int count_ = 1;
  int band_ = 1;
};

// Tiles over a width × height raster.
struct TileLayout {
  TileAxis x;
  TileAxis y;
  TileLayout() = default;
  TileLayout(int width, int height, int tile_side);  // Pre: tile_side = 2^k + 1, k >= 1
  int tile_side() const { return x.step() + 1; }
  int window_levels() const;  // n with 2^n + 1 = window side
  std::size_t tile_count() const { return static_cast<std::size_t>(x.count()) * static_cast<std::size_t>(y.count()); }
};

// True when side = 2^k + 1 with 1 <= k <= 29.
bool is_tile_side(int side);

}  // namespace mcmd
