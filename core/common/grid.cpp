#include "common/grid.hpp"

#include <algorithm>
#include <limits>
#include <stdexcept>

namespace mcmd {

Grid::Grid(int n, std::int64_t origin_x, std::int64_t origin_y)
    : n_(n), origin_x_(origin_x), origin_y_(origin_y) {
  if (n < 0 || n > 30) throw std::invalid_argument("grid levels must be in [0, 30]");
  side_ = (1 << n) + 1;
  const std::size_t cells = static_cast<std::size_t>(side_) * static_cast<std::size_t>(side_);
  z_.assign(cells, 0.0);
  s_.assign(cells, CellState::unknown);
}

std::size_t Grid::count(CellState s) const {
  return static_cast<std::size_t>(std::count(s_.begin(), s_.end(), s));
}

double known_range(std::span<const double> z, std::span<const CellState> states) {
  double lo = std::numeric_limits<double>::infinity();
  double hi = -lo;
  for (std::size_t i = 0; i < z.size(); ++i) {
    if (!is_constraint(states[i])) continue;
    lo = std::min(lo, z[i]);
    hi = std::max(hi, z[i]);
  }
  return hi >= lo ? hi - lo : 0.0;
}

double known_range(const Grid& grid) { return known_range(grid.elevations(), grid.states()); }

}  // namespace mcmd
