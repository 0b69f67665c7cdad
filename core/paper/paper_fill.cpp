#include "paper/paper_fill.hpp"

#include <stdexcept>
#include <vector>

#include "paper/mdbu.hpp"
#include "paper/midpoint_displacement.hpp"

namespace mcmd {

Scheme scheme_of(Method method) {
  if (method == Method::paper_te) return Scheme::triangle_edge;
  if (method == Method::paper_ds) return Scheme::diamond_square;
  throw std::invalid_argument("only the paper methods have a single subdivision scheme");
}

void paper_fill(Grid& grid, const FillParams& params, const ProgressFn& progress) {
  const Scheme scheme = scheme_of(params.method);
  std::vector<std::uint8_t> fixed(grid.cell_count());
  for (std::size_t i = 0; i < fixed.size(); ++i) fixed[i] = is_constraint(grid.states()[i]) ? 1 : 0;
  const double unit = params.noise_unit > 0 ? params.noise_unit : known_range(grid);
  mdbu(grid, fixed, scheme, params, sub_progress(progress, 0.0, 0.5));
  midpoint_displacement(grid, fixed, scheme, params, unit, sub_progress(progress, 0.5, 1.0));
}

}  // namespace mcmd
