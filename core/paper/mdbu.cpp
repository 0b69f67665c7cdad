#include "paper/mdbu.hpp"

#include <cmath>

#include "paper/subdivision.hpp"

namespace mcmd {

namespace {

// The 2^n+1 grid seen as a hierarchy: ascendants come from the scheme.
struct GridTopology {
  Scheme scheme;
  int n;
  int side;

  template <class F>
  void for_each_parent(std::uint32_t cell, F visit) const {
    const Parents p = parents_of(scheme, static_cast<int>(cell % side), static_cast<int>(cell / side), n);
    for (int i = 0; i < p.count; ++i)
      visit(static_cast<std::uint32_t>(p.cell[i].y) * side + static_cast<std::uint32_t>(p.cell[i].x));
  }

  double distance(std::uint32_t a, std::uint32_t b) const {
    const double dx = static_cast<double>(a % side) - static_cast<double>(b % side);
    const double dy = static_cast<double>(a / side) - static_cast<double>(b / side);
    return std::hypot(dx, dy);
  }
};

}  // namespace

double dmax_for(const Grid& grid, const FillParams& params) {
  if (params.dmax > 0) return params.dmax;
  const double span = grid.side() > 1 ? grid.side() - 1 : 1;
  return span * std::sqrt(2.0);
}

std::size_t mdbu(Grid& grid, std::vector<std::uint8_t>& fixed, Scheme scheme,
                 const FillParams& params, const ProgressFn& progress) {
  const GridTopology topology{scheme, grid.levels(), grid.side()};
  // Each wave climbs at least half a level (a diamond-square edge feeds its
  // same-level centre), so 2n + 1 waves bound the pass.
  return mdbu_waves(grid.elevations(), grid.states(), fixed, topology, params, dmax_for(grid, params),
                    2 * grid.levels() + 1, progress);
}

}  // namespace mcmd
