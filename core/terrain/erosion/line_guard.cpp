#include "terrain/erosion/line_guard.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "common/d8.hpp"

namespace mcmd::terrain {

namespace {

using d8::kDx, d8::kDy;

// The slope from river cell (x, y) to its steepest lower river neighbour;
// 0 when it has none (its end, or a flat step).
double river_slope(const Canvas& c, int x, int y) {
  const double z = c.z[c.index(x, y)];
  double best = 0.0;
  for (int k = 0; k < 8; ++k) {
    const int nx = x + kDx[k], ny = y + kDy[k];
    if (!c.contains(nx, ny) || c.state[c.index(nx, ny)] != CellState::river) continue;
    best = std::max(best, (z - c.z[c.index(nx, ny)]) / d8::length(k));
  }
  return best;
}

}  // namespace

void keep_rivers_draining(Canvas& c) {
  for (int y = 0; y < c.h; ++y)
    for (int x = 0; x < c.w; ++x) {
      const std::size_t i = c.index(x, y);
      if (c.state[i] != CellState::river) continue;
      const double s = river_slope(c, x, y);
      if (s <= 0.0) continue;
      for (int k = 0; k < 8; ++k) {
        const int nx = x + kDx[k], ny = y + kDy[k];
        if (!c.contains(nx, ny) || is_constraint(c.state[c.index(nx, ny)])) continue;
        // A free cell no steeper below (x, y) than the river, and a little less.
        double& v = c.z[c.index(nx, ny)];
        const double floor = c.z[i] - s * d8::length(k);
        // The margin survives a Float32 output.
        const double above = floor + 1e-6 * (1.0 + std::fabs(floor));
        if (v < above) v = above;
      }
    }
}

void keep_ridges_crests(Canvas& c) {
  // The highest each free cell may be: below every ridge cell within reach.
  std::vector<double> cap(c.cells(), std::numeric_limits<double>::infinity());
  bool any = false;
  for (int y = 0; y < c.h; ++y)
    for (int x = 0; x < c.w; ++x) {
      const std::size_t i = c.index(x, y);
      if (c.state[i] != CellState::ridge) continue;
      any = true;
      for (int dy = -kCrestReach; dy <= kCrestReach; ++dy)
        for (int dx = -kCrestReach; dx <= kCrestReach; ++dx) {
          const int nx = x + dx, ny = y + dy;
          if ((dx == 0 && dy == 0) || !c.contains(nx, ny)) continue;
          const std::size_t j = c.index(nx, ny);
          if (is_constraint(c.state[j])) continue;
          const double d = std::hypot(dx, dy);
          if (d > kCrestReach + 0.5) continue;
          cap[j] = std::min(cap[j], c.z[i] - 1e-6 * d * (1.0 + std::fabs(c.z[i])));
        }
    }
  if (!any) return;
  for (std::size_t i = 0; i < c.cells(); ++i) c.z[i] = std::min(c.z[i], cap[i]);
}

}  // namespace mcmd::terrain
