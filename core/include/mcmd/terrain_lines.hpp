// Ridge and river lines (mcmd/lines.hpp, read by the plugin from any OGR
// format or a raster mask) drawn into a terrain's canvas: their cells become
// ridge or river cells (crests and valleys of the terrain method).
#pragma once

#include <vector>

#include "mcmd/lines.hpp"
#include "mcmd/terrain.hpp"

namespace mcmd {

// Heights for line cells that have none of their own: empty (none), one
// value (every cell), or two (the first point's and the last point's, by
// length along the line: a river from its source down).
using LineHeights = std::vector<double>;

// A line cell on a constraint keeps its elevation and takes the line's
// state. An unknown one takes, in order: the line's own height (3D
// vertices), the straight change between the constraints where the line
// enters and leaves a run of unknown cells, the given heights. Cells outside
// the canvas are dropped. Throws std::invalid_argument when an unknown line
// cell has no height from any of these.
void draw_lines(Canvas& canvas, const std::vector<Line>& lines, const LineHeights& ridge_z,
                const LineHeights& river_z);

}  // namespace mcmd
