#include "terrain/hillshade_png.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "lib/errors.hpp"
#include "mcmd/terrain_filters.hpp"

namespace mcmd::cli {

GDALDriver* png_driver() {
  GDALDriver* d = GetGDALDriverManager()->GetDriverByName("PNG");
  if (!d) throw gdal::Failure(CPLE_IllegalArg, "GDAL has no PNG driver: -hillshade cannot be written");
  return d;
}

DatasetPtr hillshade_of(GDALRasterBand& band, const Georef& georef) {
  const int w = band.GetXSize(), h = band.GetYSize();
  std::vector<double> z(static_cast<std::size_t>(w) * h);
  gdal::check_io(band.RasterIO(GF_Read, 0, 0, w, h, z.data(), w, h, GDT_Float64, 0, 0, nullptr),
                 "cannot read the terrain back");
  int has = FALSE;
  const double nodata = band.GetNoDataValue(&has);
  double lo = INFINITY, hi = -INFINITY;
  for (double& v : z) {
    if (!std::isfinite(v) || (has && v == nodata)) v = NAN;
    else lo = std::min(lo, v), hi = std::max(hi, v);
  }
  for (double& v : z)
    if (std::isnan(v)) v = std::isfinite(lo) ? lo : 0.0;  // voids (-method none) shade flat
  double dx = 1, dy = 1;
  if (!cell_size(georef, w, h, dx, dy)) dx = dy = hi > lo ? (hi - lo) * 8.0 / std::max(w, h) : 1.0;
  std::vector<std::uint8_t> shade = hillshade(z, w, h, dx, dy);
  GDALDriver* mem = GetGDALDriverManager()->GetDriverByName("MEM");
  DatasetPtr ds(mem->Create("", w, h, 1, GDT_Byte, nullptr));
  if (!ds) throw gdal::Failure(CPLE_OutOfMemory, "cannot hold the hillshade in memory");
  gdal::check_io(ds->GetRasterBand(1)->RasterIO(GF_Write, 0, 0, w, h, shade.data(), w, h, GDT_Byte, 0, 0, nullptr),
                 "cannot make the hillshade");
  return ds;
}

}  // namespace mcmd::cli
