// The margin eroded around a raster: its own cells mirrored (the edge not
// repeated), all free. The outlets are fixed on the margin's border, so
// the lip the land leaves where it erodes below them stays in the margin,
// which is cut away; the raster's edge drains like its inside.
#pragma once

#include <vector>

#include "mcmd/terrain.hpp"

namespace mcmd::terrain {

// The margin's width for a w×h raster: 32 cells, at most a quarter of the
// shorter side.
int margin_of(int w, int h);

// c within a margin of m cells: heights mirrored, states only on c's own
// cells (the margin is free).
Canvas with_margin(const Canvas& c, int m);

// A w×h field (e.g. an uplift map) within a margin of m cells, mirrored.
std::vector<double> with_margin(const std::vector<double>& f, int w, int h, int m);

// The heights of c's own cells back from `big` (c within a margin of m).
void without_margin(const Canvas& big, int m, Canvas& c);

}  // namespace mcmd::terrain
