// The second DEM of the delta surface fill (-fill-from, FILL_FROM;
// mcmd/delta_fill.hpp), warped onto the raster's grid with GDAL and PROJ
// (any CRS, resolution and extent; bilinear or cubic).
#pragma once

#include <memory>
#include <string>

#include "gdal_priv.h"
#include "mcmd/delta_fill.hpp"

namespace mcmd::gdal {

// The second DEM on the raster's grid.
class SecondDem {
 public:
  // Throws Failure: unreadable file, no CRS or geotransform where one is
  // needed, a rotated raster, no overlap with the raster.
  SecondDem(const std::string& path, GDALDataset* target, int width, int height, const std::string& resampling);
  ~SecondDem();
  SecondDem(const SecondDem&) = delete;
  SecondDem& operator=(const SecondDem&) = delete;

  // The window's values, NaN where the second DEM has none.
  void read(int x0, int y0, int w, int h, double* s) const;
  // The second DEM's cell size, in cells of the raster (1 when on the same grid).
  double cell_ratio() const { return cell_ratio_; }

 private:
  std::string path_;
  GDALDatasetH source_ = nullptr;
  GDALDatasetH grid_ = nullptr;  // the warped VRT, or the source itself on the same grid
  double nodata_ = 0.0;
  bool has_nodata_ = false;
  double cell_ratio_ = 1.0;
};

// `second` as the core reads it (valid while `second` lives).
Background background_of(const SecondDem& second);

}  // namespace mcmd::gdal
