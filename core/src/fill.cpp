#include "mcmd/fill.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

#include "mcmd/mdbu.hpp"
#include "mcmd/midpoint_displacement.hpp"
#include "mcmd/thin_plate.hpp"

namespace mcmd {

const StateShape& shape_for(const FillParams& params, CellState s) {
  switch (s) {
    case CellState::ridge: return params.ridge_shape;
    case CellState::river: return params.river_shape;
    default: return params.known_shape;
  }
}

Scheme scheme_of(Method method) {
  if (method == Method::paper_te) return Scheme::triangle_edge;
  if (method == Method::paper_ds) return Scheme::diamond_square;
  throw std::invalid_argument("only the paper methods have a single subdivision scheme");
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

namespace {

void check_params(const Grid& grid, const FillParams& p) {
  const double values[] = {p.known_shape.I, p.known_shape.I_bu, p.ridge_shape.I, p.ridge_shape.I_bu,
                           p.river_shape.I, p.river_shape.I_bu, p.H, p.rt, p.rs, p.noise_unit, p.dmax};
  for (double v : values)
    if (!std::isfinite(v)) throw std::invalid_argument("fill parameters must be finite numbers");
  if (p.rs < 0) throw std::invalid_argument("rs must be >= 0");
  if (grid.count(CellState::unknown) == grid.cell_count())
    throw std::invalid_argument("the grid has no known cell to fill from");
}

// The paper's MCMD: MDBU then MD, on a working copy of the fixed flags.
void paper_fill(Grid& grid, const FillParams& params, const ProgressFn& progress) {
  const Scheme scheme = scheme_of(params.method);
  std::vector<std::uint8_t> fixed(grid.cell_count());
  for (std::size_t i = 0; i < fixed.size(); ++i) fixed[i] = is_constraint(grid.states()[i]) ? 1 : 0;
  const double unit = params.noise_unit > 0 ? params.noise_unit : known_range(grid);
  mdbu(grid, fixed, scheme, params, sub_progress(progress, 0.0, 0.5));
  midpoint_displacement(grid, fixed, scheme, params, unit, sub_progress(progress, 0.5, 1.0));
}

}  // namespace

void fill(Grid& grid, const FillParams& params, const ProgressFn& progress) {
  check_params(grid, params);
  report(progress, 0.0);
  if (grid.count(CellState::unknown) == 0) {
    report(progress, 1.0);
    return;
  }
  if (params.method == Method::mcmd)
    thin_plate_fill(grid, params, progress);
  else
    paper_fill(grid, params, progress);
  report(progress, 1.0);
}

}  // namespace mcmd
