// Ridge and river lines drawn on a raster (-ridges, -rivers): polylines in
// the raster's pixel coordinates. Where a line crosses a void its cells
// become ridge or river cells, constraints of the fill with heights taken
// from the known cells where the line enters and leaves the void (or given).
#pragma once

#include <limits>
#include <vector>

#include "mcmd/cell_state.hpp"

namespace mcmd {

struct LinePoint {
  double x = 0.0;  // pixel coordinates: (0, 0) is the top-left corner of cell (0, 0)
  double y = 0.0;
  double z = std::numeric_limits<double>::quiet_NaN();  // a given height, or NaN
};

struct Line {
  CellState kind = CellState::river;  // river or ridge
  std::vector<LinePoint> points;      // in the digitised order (a river's: downstream)
};

}  // namespace mcmd
