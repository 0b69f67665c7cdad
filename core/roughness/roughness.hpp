// Natural roughness for the default method: a fractal correction added to the
// smooth thin-plate fill, zero at the constraint cells and growing smoothly
// into the voids (a conditional simulation with the thin plate as the
// interpolator).
#pragma once

#include <cstdint>
#include <vector>

#include "mcmd/params.hpp"
#include "roughness/field.hpp"

namespace mcmd {

// A displacement over a box of a field (row-major, w wide), 0 outside it:
// the noise lies near the voids, a small part of a void's field.
struct Displacement {
  int x0 = 0, y0 = 0, w = 0, h = 0;  // the box, in field cells
  std::vector<double> values;        // empty: no displacement at all
  bool empty() const { return values.empty(); }
  double at(int x, int y) const;                        // any field cell
  std::vector<double> whole(int field_w, int field_h) const;  // every cell of the field
};

// The roughness of `params` for a field, as a displacement d (empty when
// there is none: -rs 0, or -rs auto with too few constraint pairs to
// estimate, or no wanted unknown cell). The fill is then one thin-plate
// solve, F = S(z − d) + d (thin_plate_with_roughness): S being linear, that is
// S(z) + (d − S(d)), the smooth fill plus the noise conditioned on the
// constraints (0 there, growing smoothly into the voids). The noise lies at
// the wanted void cells and the cells within 8 cells of one; d's box is
// their bounding box.
// rs_auto: H from estimate_roughness; the amplitude per block gives the noise
// the 5-point Laplacian variance of the terrain around it over the block's
// voids (and its neighbours') (directional semivariogram of the nearest
// constraint pairs, through a summed-area table), blending into a global
// target from estimate_roughness's curvature where too few pairs lie within
// 4 blocks. Only the octaves of spacing up to the field's depth are made (all
// when it is unknown): coarser ones are taken out by the conditioning.
// Else rs > 0: amplitude rs · noise_unit for the coarsest octave, H = params.H.
// `threads` compute a lone field's noise (same values for any count).
Displacement roughness_displacement(const RoughField& field, const FillParams& params, int threads = 1);

}  // namespace mcmd
