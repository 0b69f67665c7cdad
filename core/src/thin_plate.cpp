// Placeholder until the thin-plate default lands: the paper's diamond-square.
#include "mcmd/thin_plate.hpp"

#include "mcmd/mdbu.hpp"
#include "mcmd/midpoint_displacement.hpp"

namespace mcmd {

void thin_plate_fill(Grid& grid, const FillParams& params, const ProgressFn& progress) {
  FillParams p = params;
  p.method = Method::paper_ds;
  fill(grid, p, progress);
}

}  // namespace mcmd
