// The coarse-to-fine grids of the erosion: grid l+1 has a cell for every
// other cell of grid l (cell (X, Y) over cell (2X, 2Y)), down to at most
// kCoarsestSide cells a side. Restriction is full weighting (¼, ½, ¼ in
// each direction), prolongation Catmull-Rom: both pure functions of their
// input, so every grid is the same for any thread count.
#pragma once

#include <cstdint>
#include <vector>

#include "terrain/erosion/drainage.hpp"

namespace mcmd::terrain {

constexpr int kCoarsestSide = 320;

// Whether (x, y) lies on the border of a w×h grid: the outlets.
inline bool on_border(int x, int y, int w, int h) { return x == 0 || y == 0 || x == w - 1 || y == h - 1; }

struct ErosionGrid {
  int w = 0, h = 0;
  double spacing = 1.0;             // cell side in finest-grid cells
  int margin = 0;                   // cells of the margin around the raster (erode.cpp)
  std::vector<double> initial;      // the uneroded terrain, in finest-grid cells
  std::vector<double> uplift;       // relative uplift rate
  std::vector<std::uint8_t> fixed;  // 2: a constraint, 1: the border, 0: free
  WaterGuides guides;               // the drawn ridges and rivers
};

// The next coarser grid of g: fixed where a fixed cell of g (other than its
// border) lies in the 3×3 below, at their mean height, so that lines of
// constraints stay connected; its border fixed too; a divide where one is
// in the 3×3 below, the sources below gathered.
ErosionGrid coarser(const ErosionGrid& g);

// A w×h field on the next coarser grid (w/2+1 × h/2+1), full weighting.
std::vector<double> restrict_field(const std::vector<double>& field, int w, int h);

// A cw×ch field on the w×h grid below it.
std::vector<double> prolong(const std::vector<double>& field, int cw, int ch, int w, int h);

}  // namespace mcmd::terrain
