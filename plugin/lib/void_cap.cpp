#include "lib/void_cap.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "ogr_spatialref.h"

namespace mcmd::gdal {

namespace {

constexpr double kPi = 3.14159265358979323846;

std::string metres2(double v) { return CPLString().Printf("%.6g m2", v); }

}  // namespace

double cell_area_m2(GDALDataset& ds) {
  double gt[6];
  const OGRSpatialReference* srs = ds.GetSpatialRef();
  if (ds.GetGeoTransform(gt) != CE_None || srs == nullptr || srs->IsEmpty())
    throw OptionError("MAX_VOID as an area needs a raster with a CRS and a geotransform; give it in cells (5000cells)");
  const double area = std::fabs(gt[1] * gt[5] - gt[2] * gt[4]);
  if (!srs->IsGeographic()) {
    const double metres = srs->GetLinearUnits();
    return area * metres * metres;
  }
  // Degrees to metres at the raster's centre.
  const double lat = gt[3] + gt[4] * ds.GetRasterXSize() / 2.0 + gt[5] * ds.GetRasterYSize() / 2.0;
  OGRErr err = OGRERR_NONE;
  const double a = srs->GetSemiMajor(&err), b = srs->GetSemiMinor(&err);
  const double radius = (2 * a + b) / 3;
  const double metres_per_degree = radius * kPi / 180;
  return area * metres_per_degree * metres_per_degree * std::cos(lat * kPi / 180);
}

std::size_t void_cap_cells(const Options& o, GDALDataset* ds) {
  if (!o.max_void_in_m2) return static_cast<std::size_t>(o.max_void);
  if (ds == nullptr) throw OptionError("MAX_VOID as an area needs a band of a dataset; give it in cells (5000cells)");
  const double cell = cell_area_m2(*ds);
  const double cells = std::floor(o.max_void / cell);
  if (!(cells >= 1))
    throw OptionError("MAX_VOID=" + metres2(o.max_void) + " is smaller than one cell (" + metres2(cell) + ")");
  return static_cast<std::size_t>(std::min(cells, 1e18));
}

}  // namespace mcmd::gdal
