// Ridge and river lines (mcmd/lines.hpp) as constraint cells of the voids
// they cross.
#pragma once

#include <cstdint>
#include <utility>
#include <vector>

#include "common/grid.hpp"
#include "mcmd/lines.hpp"
#include "mcmd/raster_access.hpp"

namespace mcmd::morph {

// The cells a polyline passes through, in order along it, 8-connected, each
// once, inside the w×h raster (a line leaving and re-entering it gives one
// list with a jump). Pre: w, h >= 1.
std::vector<std::pair<int, int>> trace(const Line& line, int w, int h);

// Where a river cell lies on its run of void cells, when its height is the
// straight fall between the known cells at the run's two ends: the default
// method recomputes such heights from its own fill (channel_fill.hpp).
struct RunPlace {
  int run = -1;         // the run's number among all lines; -1: no such run
  double along = 0.0;   // length along the line from the known cell before the run
  double length = 0.0;  // from the known cell before to the known cell after
  double start_z = 0.0, end_z = 0.0;  // the heights of those two known cells
};

// A void cell on a line: a ridge or river cell of the fill.
struct LineCell {
  int x = 0, y = 0;
  CellState kind = CellState::river;
  double z = 0.0;  // NaN: from the fill (the run of void cells has a known cell at one end only)
  RunPlace place;
};

// The void cells of every line, with heights: the line's own where given,
// else for each run of void cells along a line the straight fall (rivers,
// with their RunPlace) or profile (ridges) between the known cells at its
// two ends; a run with a known cell at one end or none gets NaN (the fill
// decides: see
// channel_fill.hpp). A cell on several lines takes the first line's.
// Reads the raster along the lines. Sorted by (y, x).
std::vector<LineCell> line_cells(const RasterAccess& raster);

// Makes the unknown cells of `grid` (whose cell (0, 0) is raster cell
// (origin_x, origin_y)) that are line cells with a height ridge or river
// cells of that height (a tile's window: the tiled fill).
void place_line_cells(Grid& grid, const std::vector<LineCell>& cells);
// The same on a w×h row-major field whose cell (0, 0) is raster cell (ox, oy).
void place_line_cells(int w, int h, long long ox, long long oy, double* z, CellState* state,
                      const std::vector<LineCell>& cells);

// The line cells in rectangle [x0, x0+w) × [y0, y0+h): index range into a
// sorted list.
std::pair<std::size_t, std::size_t> cells_in_rows(const std::vector<LineCell>& cells, int y0, int h);

}  // namespace mcmd::morph
