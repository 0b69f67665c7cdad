// Checks shared by the terrain tests: polylines drawn into rasters, the
// ridge cross-profile test and the D8 flow path.
#pragma once

#include <cmath>
#include <cstddef>
#include <functional>
#include <set>
#include <utility>
#include <vector>

namespace mcmd::test {

using Cell = std::pair<int, int>;  // (x, y)

// The 8-connected cells of a polyline through `points`, each once, in order.
inline std::vector<Cell> polyline_cells(const std::vector<std::pair<double, double>>& points) {
  std::vector<Cell> out;
  for (std::size_t k = 0; k + 1 < points.size(); ++k) {
    const auto [x0, y0] = points[k];
    const auto [x1, y1] = points[k + 1];
    const int steps = static_cast<int>(std::ceil(std::max(std::fabs(x1 - x0), std::fabs(y1 - y0))));
    for (int s = 0; s <= steps; ++s) {
      const double t = steps ? static_cast<double>(s) / steps : 0.0;
      const Cell c{static_cast<int>(std::lround(x0 + t * (x1 - x0))), static_cast<int>(std::lround(y0 + t * (y1 - y0)))};
      if (out.empty() || out.back() != c) out.push_back(c);
    }
  }
  return out;
}

// Of the cells of a line (2 cells from either end), how many are higher than
// both cells 1.5 cells away across it (the line's direction taken over ±2
// cells; cells on `lines` are skipped). Returns {maxima, profiles}.
inline std::pair<int, int> ridge_maxima(const std::function<double(int, int)>& z, int w, int h,
                                        const std::vector<Cell>& line, const std::set<Cell>& lines) {
  int maxima = 0, profiles = 0;
  for (std::size_t k = 2; k + 2 < line.size(); ++k) {
    const auto [x, y] = line[k];
    const double dx = line[k + 2].first - line[k - 2].first, dy = line[k + 2].second - line[k - 2].second;
    const double L = std::hypot(dx, dy);
    double side[2];
    bool ok = true;
    for (int s = 0; s < 2; ++s) {
      const int px = static_cast<int>(std::lround(x - (s ? -1 : 1) * 1.5 * dy / L));
      const int py = static_cast<int>(std::lround(y + (s ? -1 : 1) * 1.5 * dx / L));
      if (px < 0 || py < 0 || px >= w || py >= h || lines.count({px, py})) ok = false;
      else side[s] = z(px, py);
    }
    if (!ok) continue;
    ++profiles;
    maxima += z(x, y) > side[0] && z(x, y) > side[1];
  }
  return {maxima, profiles};
}

// The D8 path from `start`: to the neighbour of steepest descent (drop over
// distance) while there is one and the border is not reached.
inline std::vector<Cell> d8_path(const std::function<double(int, int)>& z, int w, int h, Cell start) {
  std::vector<Cell> path{start};
  auto [x, y] = start;
  while (x > 0 && y > 0 && x < w - 1 && y < h - 1 && path.size() < static_cast<std::size_t>(4 * (w + h))) {
    double best = 0.0;
    Cell next{-1, -1};
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) {
        if (!dx && !dy) continue;
        const double slope = (z(x, y) - z(x + dx, y + dy)) / std::hypot(dx, dy);
        if (slope > best) best = slope, next = {x + dx, y + dy};
      }
    if (next.first < 0) break;
    x = next.first;
    y = next.second;
    path.push_back(next);
  }
  return path;
}

inline bool on_border(Cell c, int w, int h) {
  return c.first == 0 || c.second == 0 || c.first == w - 1 || c.second == h - 1;
}

}  // namespace mcmd::test
