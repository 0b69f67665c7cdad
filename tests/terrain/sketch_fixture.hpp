// The test sketch: two ridge lines across a raster and a river between them
// that descends to the right border, drawn as polylines with elevations
// varying linearly along each (as 16-bit grey levels: no flat steps).
#pragma once

#include <vector>

#include "terrain_checks.hpp"

namespace mcmd::test {

struct SketchLine {
  std::vector<Cell> cells;
  std::vector<double> z;  // per cell
  bool river = false;
};

// Lines for an n×n raster; elevations in [80, 940].
inline std::vector<SketchLine> sketch_lines(int n) {
  const double s = (n - 1) / 512.0;
  const auto scaled = [&](std::vector<std::pair<double, double>> p) {
    for (auto& [x, y] : p) x *= s, y *= s;
    return p;
  };
  const auto line = [&](std::vector<std::pair<double, double>> p, double z0, double z1, bool river) {
    SketchLine l{polyline_cells(scaled(p)), {}, river};
    for (std::size_t k = 0; k < l.cells.size(); ++k)
      l.z.push_back(z0 + (z1 - z0) * static_cast<double>(k) / static_cast<double>(l.cells.size() - 1));
    return l;
  };
  return {line({{60, 100}, {200, 150}, {330, 120}, {460, 170}}, 880, 940, false),
          line({{70, 420}, {220, 360}, {350, 390}, {470, 330}}, 840, 920, false),
          line({{120, 255}, {250, 265}, {380, 245}, {512, 255}}, 480, 80, true)};
}

// Every cell of the lines, for the cross-profile test.
inline std::set<Cell> all_cells(const std::vector<SketchLine>& lines) {
  std::set<Cell> out;
  for (const SketchLine& l : lines) out.insert(l.cells.begin(), l.cells.end());
  return out;
}

}  // namespace mcmd::test
