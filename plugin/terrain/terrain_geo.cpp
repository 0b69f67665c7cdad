#include "terrain/terrain_geo.hpp"

#include <cmath>
#include <numbers>

#include "cli/args.hpp"
#include "ogr_spatialref.h"

namespace mcmd::cli {

Georef georef_of(GDALDataset& ds) {
  Georef g;
  std::array<double, 6> t{};
  if (ds.GetGeoTransform(t.data()) == CE_None) g.transform = t;
  if (const OGRSpatialReference* srs = ds.GetSpatialRef()) {
    char* wkt = nullptr;
    if (srs->exportToWkt(&wkt) == OGRERR_NONE && wkt) g.wkt = wkt;
    CPLFree(wkt);
  }
  return g;
}

Georef supersampled(const Georef& g, int k) {
  if (!g.transform || k <= 1) return g;
  Georef out = g;
  std::array<double, 6>& t = *out.transform;
  const double shift = (k - 1) / (2.0 * k);  // coarse cells from the corner
  t[0] += shift * (t[1] + t[2]);
  t[3] += shift * (t[4] + t[5]);
  for (int i : {1, 2, 4, 5}) t[i] /= k;
  return out;
}

Georef with_overrides(Georef g, const TerrainArgs& a, int w, int h) {
  if (a.ullr) g.transform = std::array<double, 6>{a.ullr->ulx, (a.ullr->lrx - a.ullr->ulx) / w, 0.0,
                                                  a.ullr->uly, 0.0, (a.ullr->lry - a.ullr->uly) / h};
  if (!a.srs.empty()) {
    OGRSpatialReference srs;
    CPLPushErrorHandler(CPLQuietErrorHandler);
    const OGRErr err = srs.SetFromUserInput(a.srs.c_str());
    CPLPopErrorHandler();
    if (err != OGRERR_NONE) throw UsageError("-a_srs " + a.srs + ": not a CRS GDAL knows");
    char* wkt = nullptr;
    srs.exportToWkt(&wkt);
    g.wkt = wkt ? wkt : "";
    CPLFree(wkt);
  }
  return g;
}

void apply(GDALDataset& ds, const Georef& g) {
  if (g.transform) ds.SetGeoTransform(const_cast<double*>(g.transform->data()));
  if (!g.wkt.empty()) {
    OGRSpatialReference srs;
    srs.importFromWkt(g.wkt.c_str());
    ds.SetSpatialRef(&srs);
  }
}

bool cell_size(const Georef& g, int w, int h, double& dx, double& dy) {
  if (!g.transform) return false;
  const std::array<double, 6>& t = *g.transform;
  dx = std::hypot(t[1], t[4]);
  dy = std::hypot(t[2], t[5]);
  OGRSpatialReference srs;
  if (!g.wkt.empty() && srs.importFromWkt(g.wkt.c_str()) == OGRERR_NONE && srs.IsGeographic()) {
    const double lat = t[3] + t[4] * w / 2.0 + t[5] * h / 2.0;
    dx *= 111320.0 * std::cos(lat * std::numbers::pi / 180.0);
    dy *= 110574.0;
  }
  return dx > 0 && dy > 0 && std::isfinite(dx) && std::isfinite(dy);
}

}  // namespace mcmd::cli
