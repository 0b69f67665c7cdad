// The hillslope processes of an eroding terrain, between the channels:
//   * soil creep, linear diffusion ∂z/∂t = D·∇²z, one implicit step split
//     along the rows then the columns (each a tridiagonal solve): stable for
//     any time step, so it keeps pace with the implicit stream power;
//   * failure above the angle of repose: no cell stands more than
//     tan(talus) · distance above a neighbour (the excess slides away).
// Fixed cells keep their heights and hold their neighbours as boundaries.
#pragma once

#include <cstdint>
#include <vector>

namespace mcmd::terrain {

// One implicit diffusion step of D·dt (in cells² of this grid). Row and
// column solves run on `threads`; the same bits for any count.
void diffuse(std::vector<double>& z, const std::vector<std::uint8_t>& fixed, int w, int h, double d_dt, int threads);

// Lower every free cell that stands more than `slope` · distance (heights
// in cells of this grid) above a neighbour: two sweeps, forward and back,
// which carry the limit along any 8-connected path.
void limit_slopes(std::vector<double>& z, const std::vector<std::uint8_t>& fixed, int w, int h, double slope);

}  // namespace mcmd::terrain
