// Seam blending of window results into final raster values (docs/tiling.md).
//
// A cell's value is Σ w_tx(x)·w_ty(y)·F_(tx,ty)(x, y) over the windows whose
// output region holds it (at most 2×2), summed in row-major tile order; in a
// tile's solo zone it is the window value itself, bit for bit. Only void cells
// flagged by the window that owns the cell (TileAxis::owner) are written.
//
// Memory: the two horizontal seam bands of the current tile row (the
// blender's columns: full width unless told, 2b-1 rows each) and one vertical seam band of the current tile (solo rows ×
// 2b-1 columns) — bounded by tile size and raster width, never raster height.
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include "raster/tiles/tile_layout.hpp"

namespace mcmd {

// One window's fill over its tile's output region.
struct WindowResult {
  int tx = 0;
  int ty = 0;
  Range xs;                         // layout.x.region(tx)
  Range ys;                         // layout.y.region(ty)
  std::vector<double> z;            // xs.size() × ys.size(), row-major
  std::vector<std::uint8_t> write;  // 1: a void cell this window would write
};

// Writes the cells of rectangle [x0, x0+w) × [y0, y0+h) where mask is set.
using BlockWriter =
    std::function<void(int x0, int y0, int w, int h, const double* z, const std::uint8_t* mask)>;

class Blender {
 public:
  // Seam bands are kept over `cols` only (default: every column); cells
  // outside it may be written wrong (a caller that keeps only a part of the
  // raster, mcmd/chunked_fill.hpp, gives the part's columns).
  Blender(const TileLayout& layout, BlockWriter write);
  Blender(const TileLayout& layout, BlockWriter write, Range cols);

  // Pre: results come in row-major tile order (ty, then tx, increasing);
  // tiles whose region has no void may be left out. Writes what is final.
  void add(const WindowResult& r);
  // After the last add() of tile row ty; call once per tile row, in order.
  void end_row(int ty);

 private:
  struct Strip {  // a horizontal seam band, full raster width
    int seam = -1;
    Range rows;
    std::vector<double> z;
    std::vector<std::uint8_t> mask;
  };
  struct Pending {  // the right seam band of the previous tile, solo rows only
    int tx = -1;
    int ty = -1;
    Range cols;
    Range rows;
    std::vector<double> z;
    std::vector<std::uint8_t> mask;
  };

  Strip& strip_for(int seam);
  void add_to_strip(const WindowResult& r, int seam);
  void add_solo_rows(const WindowResult& r);
  void flush_strip(Strip& s);
  void emit(int x0, int y0, int w, int h, const double* z, const std::uint8_t* mask, int stride);
  // wx_ and own_x_ for the columns of r (a quintic ramp and a division per
  // column, not per cell).
  void columns_of(const WindowResult& r);

  TileLayout layout_;
  BlockWriter write_;
  Range cols_;
  Strip top_, bottom_;
  Pending pending_;
  std::vector<double> zbuf_;
  std::vector<std::uint8_t> mbuf_;
  std::vector<double> wx_;          // per column of the current result: its x weight
  std::vector<std::uint8_t> own_x_; // 1: the column is owned by its tile
};

}  // namespace mcmd
