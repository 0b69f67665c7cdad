#include "lib/line_input.hpp"

#include <cmath>
#include <memory>

#include "lib/errors.hpp"
#include "ogr_geometry.h"
#include "ogr_spatialref.h"
#include "ogrsf_frmts.h"

namespace mcmd::gdal {

namespace {

struct DatasetCloser {
  void operator()(GDALDataset* ds) const { GDALClose(GDALDataset::ToHandle(ds)); }
};
using Owned = std::unique_ptr<GDALDataset, DatasetCloser>;

struct TransformDeleter {
  void operator()(OGRCoordinateTransformation* ct) const { OGRCoordinateTransformation::DestroyCT(ct); }
};

std::string quoted(const std::string& path) { return "'" + path + "'"; }

// Map coordinates of the raster's CRS to pixel coordinates.
class PixelMapper {
 public:
  explicit PixelMapper(GDALDataset& raster) {
    double gt[6] = {0, 1, 0, 0, 0, 1};
    if (raster.GetGeoTransform(gt) != CE_None) gt[5] = 1.0;  // no geotransform: pixel = map coordinates
    if (!GDALInvGeoTransform(gt, inv_)) throw Failure(CPLE_AppDefined, "the raster's geotransform is not invertible");
  }
  LinePoint operator()(double x, double y, double z) const {
    return LinePoint{inv_[0] + inv_[1] * x + inv_[2] * y, inv_[3] + inv_[4] * x + inv_[5] * y, z};
  }

 private:
  double inv_[6];
};

void add_line_string(const OGRLineString& ls, OGRCoordinateTransformation* ct, const PixelMapper& to_pixel,
                     CellState kind, const std::string& path, std::vector<Line>& out) {
  Line line;
  line.kind = kind;
  const bool has_z = ls.Is3D();
  for (int k = 0; k < ls.getNumPoints(); ++k) {
    double x = ls.getX(k), y = ls.getY(k), z = has_z ? ls.getZ(k) : 0.0;
    if (ct && !ct->Transform(1, &x, &y, &z))
      throw Failure(CPLE_AppDefined, "cannot transform the lines of " + quoted(path) + " to the raster's CRS");
    line.points.push_back(to_pixel(x, y, has_z ? z : std::nan("")));
  }
  if (!line.points.empty()) out.push_back(std::move(line));
}

void add_geometry(const OGRGeometry* g, OGRCoordinateTransformation* ct, const PixelMapper& to_pixel, CellState kind,
                  const std::string& path, std::vector<Line>& out) {
  if (!g) return;
  const OGRwkbGeometryType t = wkbFlatten(g->getGeometryType());
  if (t == wkbLineString) {
    add_line_string(*g->toLineString(), ct, to_pixel, kind, path, out);
  } else if (t == wkbMultiLineString || t == wkbGeometryCollection) {
    for (const OGRGeometry* part : *g->toGeometryCollection()) add_geometry(part, ct, to_pixel, kind, path, out);
  }
}

std::vector<Line> read_vector(GDALDataset& ds, const std::string& path, CellState kind, GDALDataset& raster) {
  const PixelMapper to_pixel(raster);
  const OGRSpatialReference* target = raster.GetSpatialRef();
  std::vector<Line> out;
  for (OGRLayer* layer : ds.GetLayers()) {
    const OGRSpatialReference* source = layer->GetSpatialRef();
    std::unique_ptr<OGRCoordinateTransformation, TransformDeleter> ct;
    if (source && target && !source->IsSame(target)) {
      CPLPushErrorHandler(CPLQuietErrorHandler);
      ct.reset(OGRCreateCoordinateTransformation(source, target));
      CPLPopErrorHandler();
      if (!ct)
        throw Failure(CPLE_AppDefined, "cannot transform the lines of " + quoted(path) + " from their CRS (" +
                                           (source->GetName() ? source->GetName() : "unnamed") +
                                           ") to the raster's CRS");
    } else if (!source && target && layer->GetFeatureCount() > 0) {
      throw Failure(CPLE_AppDefined, "the lines of " + quoted(path) +
                                         " have no coordinate reference system (assign one, e.g. ogr2ogr -a_srs)");
    }
    layer->ResetReading();
    for (auto& feature : *layer) add_geometry(feature->GetGeometryRef(), ct.get(), to_pixel, kind, path, out);
  }
  return out;
}

// A mask's nonzero cells as lines: each walk from an end cell (one neighbour
// or none) along unvisited neighbours, in raster order, through cell centres.
std::vector<Line> read_mask(GDALDataset& ds, const std::string& path, CellState kind, GDALDataset& raster) {
  const int w = raster.GetRasterXSize(), h = raster.GetRasterYSize();
  if (ds.GetRasterXSize() != w || ds.GetRasterYSize() != h)
    throw Failure(CPLE_IllegalArg, "line mask " + quoted(path) + " is " + std::to_string(ds.GetRasterXSize()) + "x" +
                                       std::to_string(ds.GetRasterYSize()) + " but the raster is " +
                                       std::to_string(w) + "x" + std::to_string(h));
  std::vector<std::uint8_t> on(static_cast<std::size_t>(w) * h);
  check_io(ds.GetRasterBand(1)->RasterIO(GF_Read, 0, 0, w, h, on.data(), w, h, GDT_Byte, 0, 0, nullptr),
           "cannot read the line mask");
  const auto at = [&](int x, int y) { return x >= 0 && y >= 0 && x < w && y < h && on[static_cast<std::size_t>(y) * w + x]; };
  const auto degree = [&](int x, int y) {
    int n = 0;
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) n += (dx || dy) && at(x + dx, y + dy);
    return n;
  };
  std::vector<Line> out;
  const auto walk = [&](int x, int y) {
    Line line;
    line.kind = kind;
    while (true) {
      on[static_cast<std::size_t>(y) * w + x] = 0;
      line.points.push_back(LinePoint{x + 0.5, y + 0.5});
      bool moved = false;
      for (int k = 0; k < 8 && !moved; ++k) {
        static constexpr int dx[8] = {1, 0, -1, 0, 1, -1, -1, 1}, dy[8] = {0, 1, 0, -1, 1, 1, -1, -1};
        if (at(x + dx[k], y + dy[k])) x += dx[k], y += dy[k], moved = true;
      }
      if (!moved) break;
    }
    out.push_back(std::move(line));
  };
  for (int pass = 0; pass < 2; ++pass)  // ends first, then what is left (loops)
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x)
        if (at(x, y) && (pass == 1 || degree(x, y) <= 1)) walk(x, y);
  return out;
}

}  // namespace

std::vector<Line> read_lines(const std::string& path, CellState kind, GDALDataset& raster) {
  const char* what = kind == CellState::ridge ? "ridge" : "river";
  CPLErrorReset();
  Owned ds(GDALDataset::Open(path.c_str(), GDAL_OF_VECTOR | GDAL_OF_RASTER | GDAL_OF_READONLY));
  if (!ds) {
    const std::string why = CPLGetLastErrorMsg();
    throw Failure(CPLE_OpenFailed, std::string("cannot read the ") + what + " lines " + quoted(path) + ": " +
                                       (why.empty() ? "not a vector or raster format GDAL can read" : why));
  }
  std::vector<Line> lines = ds->GetLayerCount() > 0 ? read_vector(*ds, path, kind, raster)
                            : ds->GetRasterCount() > 0 ? read_mask(*ds, path, kind, raster)
                                                       : std::vector<Line>{};
  if (lines.empty())
    throw Failure(CPLE_AppDefined, std::string("the ") + what + " file " + quoted(path) + " holds no line");
  return lines;
}

std::size_t lines_inside(const std::vector<Line>& lines, int w, int h) {
  std::size_t n = 0;
  for (const Line& l : lines) {
    bool in = false;
    for (std::size_t k = 0; k < l.points.size() && !in; ++k) {
      const LinePoint& p = l.points[k];
      in = p.x >= 0 && p.y >= 0 && p.x < w && p.y < h;
      // a segment may cross the raster with both ends outside
      if (!in && k > 0) {
        const LinePoint& a = l.points[k - 1];
        for (int s = 1; s < 64 && !in; ++s) {
          const double t = s / 64.0, x = a.x + t * (p.x - a.x), y = a.y + t * (p.y - a.y);
          in = x >= 0 && y >= 0 && x < w && y < h;
        }
      }
    }
    n += in;
  }
  return n;
}

}  // namespace mcmd::gdal
