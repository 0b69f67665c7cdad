// The C API's MCMDTerrain(): terrain_band.hpp behind GDAL's error contract.
#include "lib/errors.hpp"
#include "lib/terrain_band.hpp"
#include "lib/terrain_options.hpp"
#include "mcmd_gdal.h"

extern "C" CPLErr MCMDTerrain(GDALRasterBandH hTargetBand, GDALRasterBandH hSketchBand, CSLConstList papszOptions,
                              GDALProgressFunc pfnProgress, void* pProgressArg) {
  using namespace mcmd::gdal;
  return guarded([&] {
    if (!hTargetBand) throw Failure(CPLE_ObjectNull, "MCMDTerrain: hTargetBand is NULL");
    const TerrainOptions options = parse_terrain_options(papszOptions);
    GDALRasterBand* sketch = hSketchBand ? GDALRasterBand::FromHandle(hSketchBand) : nullptr;
    mcmd::ProgressFn progress;
    if (pfnProgress)
      progress = [pfnProgress, pProgressArg](double f) { return pfnProgress(f, "", pProgressArg) != FALSE; };
    make_terrain(*GDALRasterBand::FromHandle(hTargetBand), sketch, options, progress);
  });
}
