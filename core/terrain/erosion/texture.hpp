// The texture of the eroded terrain: the uneroded terrain's finest octave,
// put back after the erosion. Creep rounds the finest grid's cells, so the
// eroded surface is smoother at the cell scale than at any scale above it:
// a plastic sheen in the hillshade, and none of the small pits that a real
// DEM holds on its gentler ground (a few metres deep, one or two cells).
#pragma once

#include <vector>

#include "terrain/erosion/pyramid.hpp"

namespace mcmd::terrain {

// Adds to the free cells of z (g's finest grid, heights in its cells) the
// finest octave of g.initial (the detail that the next coarser grid cannot
// hold), scaled so that z's finest octave ends at 0.4 of its second finest
// (RMS over the free cells of the raster, its margin aside). Nothing when
// the erosion left that much. Pure function of z and g: the same for any
// thread count.
void restore_texture(std::vector<double>& z, const ErosionGrid& g);

}  // namespace mcmd::terrain
