#include "mcmd/terrain_lines.hpp"

#include <cmath>
#include <map>
#include <stdexcept>
#include <utility>

#include "morphology/lines.hpp"

namespace mcmd {

namespace {

// The canvas as the raster morphology's line_cells reads.
RasterAccess access_of(const Canvas& c, const std::vector<Line>& lines) {
  RasterAccess a;
  a.width = c.w;
  a.height = c.h;
  a.read = [&c](int x0, int y0, int w, int h, double* z, std::uint8_t* valid) {
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        const std::size_t i = c.index(x0 + x, y0 + y), o = static_cast<std::size_t>(y) * w + x;
        z[o] = c.z[i];
        valid[o] = is_constraint(c.state[i]);
      }
  };
  a.write = [](int, int, int, int, const double*, const std::uint8_t*) {};
  a.lines = lines;
  return a;
}

// The given heights at arc length s of a line of length L; NaN: none.
double given(const LineHeights& z, double s, double L) {
  if (z.empty()) return NAN;
  if (z.size() == 1 || L <= 0) return z.front();
  return z[0] + (z[1] - z[0]) * (s / L);
}

}  // namespace

void draw_lines(Canvas& c, const std::vector<Line>& lines, const LineHeights& ridge_z, const LineHeights& river_z) {
  std::map<std::pair<int, int>, double> own;  // heights of unknown line cells from the lines and the constraints
  for (const morph::LineCell& cell : morph::line_cells(access_of(c, lines)))
    if (std::isfinite(cell.z)) own.emplace(std::make_pair(cell.x, cell.y), cell.z);
  for (const Line& line : lines) {
    const std::vector<std::pair<int, int>> cells = morph::trace(line, c.w, c.h);
    std::vector<double> along(cells.size(), 0.0);
    for (std::size_t k = 1; k < cells.size(); ++k)
      along[k] = along[k - 1] + std::hypot(cells[k].first - cells[k - 1].first, cells[k].second - cells[k - 1].second);
    const LineHeights& heights = line.kind == CellState::ridge ? ridge_z : river_z;
    for (std::size_t k = 0; k < cells.size(); ++k) {
      const auto [x, y] = cells[k];
      const std::size_t i = c.index(x, y);
      if (is_constraint(c.state[i])) {
        c.state[i] = line.kind;
        continue;
      }
      const auto it = own.find(cells[k]);
      const double z = it != own.end() ? it->second : given(heights, along[k], along.back());
      if (!std::isfinite(z))
        throw std::invalid_argument(std::string("the ") + (line.kind == CellState::ridge ? "ridge" : "river") +
                                    " lines cross unknown cells without a height there: give " +
                                    (line.kind == CellState::ridge ? "-ridge-z (RIDGE_Z)" : "-river-z (RIVER_Z)") +
                                    ", lines with Z, or draw them over the sketch");
      c.set(x, y, z, line.kind);
    }
  }
}

}  // namespace mcmd
