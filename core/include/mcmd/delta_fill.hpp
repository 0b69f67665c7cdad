// The delta surface fill (-fill-from; Grohman, Kroenung & Strebeck 2006):
// where a second DEM of the area exists, a void takes its shape and only the
// difference between the two DEMs is interpolated across the void, so that
// the fill meets the rim without a step.
//
// The difference D = z − s at the known cells (0 where s has no value) is
// filled across each void by the chosen method and faded towards 0 with the
// distance d from the rim: fill = s + D·exp(−(d − 1)/L). The thin plate alone
// carries the rim's high-frequency differences deep into the void; the fade
// keeps them near the rim. L is the longer of the second DEM's cell size (in
// cells of the raster) and the correlation length of D along the rows (the
// lag where its autocorrelation falls below 1/e), within [1, 256]. Void cells
// where s has no value get the plain fill (a first pass, only when there are
// such cells). With roughness, D is also filled smooth (D̂) and the fill is
// s + D − (1 − fade)·D̂: the relief (D − D̂, 0 at the data) is not faded.
#pragma once

#include <functional>

#include "mcmd/params.hpp"
#include "mcmd/progress.hpp"
#include "mcmd/raster_access.hpp"

namespace mcmd {

// The second DEM on the raster's grid.
struct Background {
  // Cells [x0, x0+w) × [y0, y0+h), row-major; NaN where it has no value.
  // Called from the thread that calls fill_raster_from only.
  std::function<void(int x0, int y0, int w, int h, double* s)> read;
  double cell_ratio = 1.0;  // its cell size in cells of the raster
};

// fill_raster (mcmd/fill_raster.hpp) with the delta surface inside the voids;
// throws as fill_raster.
void fill_raster_from(const RasterAccess& raster, const Background& second, const FillParams& params,
                      const TilingParams& tiling, const ProgressFn& progress = {}, const RasterFillHooks& hooks = {});

}  // namespace mcmd
