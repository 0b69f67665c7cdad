// The relief the river particles run on (skeleton.hpp, seed 001 §2.3): the
// ridge routes blended with Gaussian cross-profiles of σ' = σ/4 (the highest
// profile wins), plus a low dome that leans every flat towards the border.
// Smooth at the scale of σ', it is held on a lattice of spacing ~σ'/4 and
// read through Catmull-Rom splines.
#pragma once

#include <vector>

#include "terrain/skeleton/ridge_particles.hpp"

namespace mcmd::terrain {

class RidgeRelief {
 public:
  // top: the relief's scale (the highest start height).
  RidgeRelief(int w, int h, const RidgeRoutes& routes, double top);

  // Height above the base at a point of the raster (cell coordinates).
  double at(double x, double y) const;
  // Its gradient (central differences half a cell apart).
  void gradient(double x, double y, double& gx, double& gy) const;
  // at() at every cell centre, row-major.
  std::vector<double> cells() const;
  double cross_sigma() const { return cross_sigma_; }

  // Lower the relief along a river through (x, y): a Gaussian trough of
  // `depth` and σ `width` (the deepest trough wins where they overlap), so
  // later particles drain into the valleys of earlier ones instead of
  // running beside them down the same slope.
  void dig(double x, double y, double depth, double width);

 private:
  double node(int i, int j) const;
  int w_, h_, stride_, nx_, ny_;
  double cross_sigma_;
  std::vector<double> lattice_;
  std::vector<double> trough_;  // per node, the depth dug there
};

}  // namespace mcmd::terrain
