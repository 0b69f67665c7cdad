#include "lib/fill_from.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "cpl_string.h"
#include "gdal_utils.h"
#include "lib/errors.hpp"
#include "ogr_spatialref.h"

namespace mcmd::gdal {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

[[noreturn]] void fail(const std::string& path, const std::string& why) {
  throw Failure(CPLE_AppDefined, "FILL_FROM '" + path + "' " + why);
}

struct Bounds {
  double x0 = 0, y0 = 0, x1 = 0, y1 = 0;  // min x, min y, max x, max y
};

Bounds bounds_of(const double gt[6], int w, int h) {
  return Bounds{gt[0], gt[3] + gt[5] * h, gt[0] + gt[1] * w, gt[3]};
}

// The source's extent in the target's CRS (its border, 16 points a side).
Bounds bounds_in(GDALDatasetH source, const OGRSpatialReference& to, const std::string& path) {
  double gt[6];
  GDALGetGeoTransform(source, gt);
  const int w = GDALGetRasterXSize(source), h = GDALGetRasterYSize(source);
  OGRSpatialReference from(*reinterpret_cast<const OGRSpatialReference*>(GDALGetSpatialRef(source)));
  from.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
  OGRSpatialReference target(to);
  target.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
  std::unique_ptr<OGRCoordinateTransformation> ct(OGRCreateCoordinateTransformation(&from, &target));
  if (!ct) fail(path, "has a CRS that cannot be transformed to the raster's");
  std::vector<double> xs, ys;
  for (int k = 0; k <= 16; ++k) {
    const double f = k / 16.0;
    const double px[4] = {f * w, f * w, 0, double(w)}, py[4] = {0, double(h), f * h, f * h};
    for (int e = 0; e < 4; ++e) {
      xs.push_back(gt[0] + px[e] * gt[1] + py[e] * gt[2]);
      ys.push_back(gt[3] + px[e] * gt[4] + py[e] * gt[5]);
    }
  }
  std::vector<int> ok(xs.size());
  ct->Transform(static_cast<int>(xs.size()), xs.data(), ys.data(), nullptr, ok.data());
  Bounds b{std::numeric_limits<double>::max(), std::numeric_limits<double>::max(),
           std::numeric_limits<double>::lowest(), std::numeric_limits<double>::lowest()};
  bool any = false;
  for (std::size_t i = 0; i < xs.size(); ++i) {
    if (!ok[i] || !std::isfinite(xs[i]) || !std::isfinite(ys[i])) continue;
    any = true;
    b.x0 = std::min(b.x0, xs[i]), b.x1 = std::max(b.x1, xs[i]);
    b.y0 = std::min(b.y0, ys[i]), b.y1 = std::max(b.y1, ys[i]);
  }
  if (!any) fail(path, "lies where the raster's CRS is not defined");
  return b;
}

bool georeferenced(GDALDatasetH ds) {
  double gt[6];
  const OGRSpatialReference* srs = GDALDataset::FromHandle(ds)->GetSpatialRef();
  return GDALGetGeoTransform(ds, gt) == CE_None && srs != nullptr && !srs->IsEmpty();
}

}  // namespace

SecondDem::SecondDem(const std::string& path, GDALDataset* target, int width, int height,
                     const std::string& resampling)
    : path_(path) {
  source_ = GDALOpenEx(path.c_str(), GDAL_OF_RASTER | GDAL_OF_VERBOSE_ERROR, nullptr, nullptr, nullptr);
  if (!source_) fail(path, "cannot be opened as a raster: " + std::string(CPLGetLastErrorMsg()));
  GDALRasterBandH band = GDALGetRasterBand(source_, 1);
  if (!band) fail(path, "has no band");
  int has = 0;
  nodata_ = GDALGetRasterNoDataValue(band, &has);
  has_nodata_ = has != 0;
  const GDALDatasetH target_h = GDALDataset::ToHandle(target);
  const bool same_size = GDALGetRasterXSize(source_) == width && GDALGetRasterYSize(source_) == height;
  if (!target || !georeferenced(target_h) || !georeferenced(source_)) {
    // Without georeferencing on both sides, only a grid of the same size can be used, cell for cell.
    if (!same_size)
      fail(path, "and the raster are not both georeferenced (CRS and geotransform), and their sizes differ");
    grid_ = source_;
    return;
  }
  double gt[6];
  target->GetGeoTransform(gt);
  if (gt[2] != 0 || gt[4] != 0) fail(path, "cannot be warped onto a rotated raster");
  const Bounds t = bounds_of(gt, width, height);
  const Bounds s = bounds_in(source_, *target->GetSpatialRef(), path);
  if (s.x1 <= t.x0 || s.x0 >= t.x1 || s.y1 <= t.y0 || s.y0 >= t.y1) fail(path, "does not overlap the raster");
  // Its cell size in the raster's cells: the extent's width over its columns.
  cell_ratio_ = std::max(1.0, (s.x1 - s.x0) / GDALGetRasterXSize(source_) / std::fabs(gt[1]));

  char* wkt = nullptr;
  target->GetSpatialRef()->exportToWkt(&wkt);
  CPLStringList args;
  for (const char* a : {"-of", "VRT", "-ot", "Float64", "-dstnodata", "nan", "-r"}) args.AddString(a);
  args.AddString(resampling.c_str());
  args.AddString("-t_srs");
  args.AddString(wkt);
  CPLFree(wkt);
  args.AddString("-te");
  for (double v : {t.x0, t.y0, t.x1, t.y1}) args.AddString(CPLSPrintf("%.17g", v));
  args.AddString("-ts");
  args.AddString(CPLSPrintf("%d", width));
  args.AddString(CPLSPrintf("%d", height));
  GDALWarpAppOptions* options = GDALWarpAppOptionsNew(args.List(), nullptr);
  GDALDatasetH sources[1] = {source_};
  int usage_error = 0;
  grid_ = GDALWarp("", nullptr, 1, sources, options, &usage_error);
  GDALWarpAppOptionsFree(options);
  if (!grid_) fail(path, "cannot be warped onto the raster's grid: " + std::string(CPLGetLastErrorMsg()));
  has_nodata_ = false;  // the warp's nodata is NaN
}

SecondDem::~SecondDem() {
  if (grid_ && grid_ != source_) GDALClose(grid_);
  if (source_) GDALClose(source_);
}

void SecondDem::read(int x0, int y0, int w, int h, double* s) const {
  GDALRasterBandH band = GDALGetRasterBand(grid_, 1);
  if (GDALRasterIO(band, GF_Read, x0, y0, w, h, s, w, h, GDT_Float64, 0, 0) != CE_None)
    fail(path_, "could not be read: " + std::string(CPLGetLastErrorMsg()));
  const std::size_t n = static_cast<std::size_t>(w) * h;
  for (std::size_t i = 0; i < n; ++i)
    if (!std::isfinite(s[i]) || (has_nodata_ && s[i] == nodata_)) s[i] = kNaN;
}

Background background_of(const SecondDem& second) {
  Background b;
  b.read = [&second](int x0, int y0, int w, int h, double* s) { second.read(x0, y0, w, h, s); };
  b.cell_ratio = second.cell_ratio();
  return b;
}

}  // namespace mcmd::gdal
