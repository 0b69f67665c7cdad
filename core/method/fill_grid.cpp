#include "method/fill_grid.hpp"

#include <cmath>
#include <stdexcept>

#include "paper/paper_fill.hpp"
#include "thin_plate/thin_plate.hpp"

namespace mcmd {

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

}  // namespace

void fill_grid(Grid& grid, const FillParams& params, const ProgressFn& progress) {
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
