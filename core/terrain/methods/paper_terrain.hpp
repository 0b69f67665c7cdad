// The paper's methods on a canvas of any size: the canvas is the top-left
// part of the smallest 2^n+1 grid covering it (the rest unknown, computed and
// dropped), filled by MDBU then MD (TerrainMethod::paper), or by the older
// MDI then plain MD (TerrainMethod::mdi, mdi.hpp), on the chosen scheme.
#pragma once

#include "mcmd/progress.hpp"
#include "mcmd/terrain.hpp"
#include "paper/subdivision.hpp"

namespace mcmd::terrain {

Scheme scheme_of(TerrainScheme s);

// Pre: params.method is paper or mdi. Post: as synthesize().
void paper_terrain(Canvas& canvas, const TerrainParams& params, double unit, const ProgressFn& progress);

}  // namespace mcmd::terrain
