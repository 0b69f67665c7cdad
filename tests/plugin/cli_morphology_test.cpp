// mcmd_fillnodata's morphology end to end: -morph auto, and ridge and river
// lines read from real GeoPackages (in another CRS) and raster masks.
#include <cmath>
#include <functional>
#include <gtest/gtest.h>
#include <memory>

#include "morphology/flow.hpp"
#include "ogr_spatialref.h"
#include "ogrsf_frmts.h"
#include "test_support.hpp"

namespace mcmd::test {
namespace {

constexpr int kW = 101, kH = 101;
constexpr double kX0 = 400000.0, kY0 = 3800000.0, kCell = 30.0;  // EPSG:32611, 30 m cells

// An Int16 GeoTIFF of f over a kW × kH grid, a disc of radius 20 at the
// centre set to nodata.
void write_dem(const std::string& path, const std::function<double(int, int)>& f) {
  GDALDriver* gtiff = GetGDALDriverManager()->GetDriverByName("GTiff");
  GDALDataset* ds = gtiff->Create(path.c_str(), kW, kH, 1, GDT_Int16, nullptr);
  OGRSpatialReference srs;
  srs.importFromEPSG(32611);
  ds->SetSpatialRef(&srs);
  double gt[6] = {kX0, kCell, 0, kY0, 0, -kCell};
  ds->SetGeoTransform(gt);
  std::vector<std::int16_t> v(static_cast<std::size_t>(kW) * kH);
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x)
      v[static_cast<std::size_t>(y) * kW + x] =
          std::hypot(x - 50, y - 50) <= 20 ? -32768 : static_cast<std::int16_t>(std::lround(f(x, y)));
  ds->GetRasterBand(1)->SetNoDataValue(-32768);
  EXPECT_EQ(ds->GetRasterBand(1)->RasterIO(GF_Write, 0, 0, kW, kH, v.data(), kW, kH, GDT_Int16, 0, 0, nullptr), CE_None);
  GDALClose(ds);
}

bool in_void(int x, int y) { return std::hypot(x - 50, y - 50) <= 20; }

// The river used by the tests: pixel coordinates, meandering across the
// plane's own slope.
std::vector<std::pair<double, double>> river_pixels() {
  std::vector<std::pair<double, double>> p;
  for (int y = 0; y <= 100; y += 4) p.emplace_back(50.5 + 12.0 * std::sin(y / 12.0), y + 0.5);
  return p;
}
double plane(int x, int y) { return 500.0 - 1.0 * y - 0.3 * x; }

// A GeoPackage with one layer in EPSG:<epsg> holding `lines` given in pixel
// coordinates of the test grid (transformed), or points when `points`.
void write_lines(const std::string& path, int epsg, const std::vector<std::vector<std::pair<double, double>>>& lines,
                 bool points = false, bool with_crs = true) {
  GDALDriver* gpkg = GetGDALDriverManager()->GetDriverByName("GPKG");
  GDALDataset* ds = gpkg->Create(path.c_str(), 0, 0, 0, GDT_Unknown, nullptr);
  OGRSpatialReference utm, target;
  utm.importFromEPSG(32611);
  target.importFromEPSG(epsg);
  utm.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
  target.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
  std::unique_ptr<OGRCoordinateTransformation> ct(OGRCreateCoordinateTransformation(&utm, &target));
  OGRLayer* layer = ds->CreateLayer("lines", with_crs ? &target : nullptr, points ? wkbPoint : wkbLineString, nullptr);
  for (const auto& line : lines) {
    OGRFeature f(layer->GetLayerDefn());
    OGRLineString ls;
    for (const auto& [px, py] : line) {
      double x = kX0 + px * kCell, y = kY0 - py * kCell;
      ct->Transform(1, &x, &y);
      ls.addPoint(x, y);
    }
    if (points) {
      OGRPoint pt(ls.getX(0), ls.getY(0));
      f.SetGeometry(&pt);
    } else {
      f.SetGeometry(&ls);
    }
    EXPECT_EQ(layer->CreateFeature(&f), OGRERR_NONE);
  }
  GDALClose(ds);
}

double at(const std::vector<double>& v, int x, int y) { return v[static_cast<std::size_t>(y) * kW + x]; }

// Cells of the D8 path from (x, y) while inside the void: steepest descent
// on the levels of Priority-Flood with ε, which resolves the flats of an
// integer DEM as every hydrological tool does.
std::vector<std::pair<int, int>> path_in_void(const std::vector<double>& values, int x, int y) {
  const std::vector<morph::FlowCell> land(values.size(), morph::FlowCell::land);
  const std::vector<double> v = morph::flood_levels(values.data(), kW, kH, land.data());
  std::vector<std::pair<int, int>> path;
  while (in_void(x, y)) {
    path.emplace_back(x, y);
    int bx = -1, by = -1;
    double best = 0;
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) {
        const int nx = x + dx, ny = y + dy;
        if ((!dx && !dy) || nx < 0 || ny < 0 || nx >= kW || ny >= kH) continue;
        const double s = (at(v, x, y) - at(v, nx, ny)) / std::hypot(dx, dy);
        if (s > best) best = s, bx = nx, by = ny;
      }
    if (bx < 0) break;
    x = bx, y = by;
  }
  return path;
}

// How many cells of the path lie within a cell of the river line.
int near_river(const std::vector<std::pair<int, int>>& path) {
  const auto p = river_pixels();
  int n = 0;
  for (const auto& [x, y] : path) {
    bool near = false;
    for (std::size_t k = 1; k < p.size() && !near; ++k)
      for (int s = 0; s <= 16 && !near; ++s) {
        const double t = s / 16.0, lx = p[k - 1].first + t * (p[k].first - p[k - 1].first),
                     ly = p[k - 1].second + t * (p[k].second - p[k - 1].second);
        near = std::abs(std::floor(lx) - x) <= 1 && std::abs(std::floor(ly) - y) <= 1;
      }
    n += near;
  }
  return n;
}

// The first cell of the river inside the void.
std::pair<int, int> river_entry() {
  for (const auto& [x, y] : river_pixels())
    if (in_void(static_cast<int>(x), static_cast<int>(y))) return {static_cast<int>(x), static_cast<int>(y)};
  return {50, 30};
}

TEST(CliMorphology, ARiverInAGeoPackageOfAnotherCrsIsFollowedThroughTheVoid) {
  TempDir dir;
  const std::string src = dir.file("dem.tif"), dst = dir.file("out.tif"), plain = dir.file("plain.tif"),
                    rivers = dir.file("rivers.gpkg");
  write_dem(src, plane);
  write_lines(rivers, 4326, {river_pixels()});
  const RunResult r = run_cli({"-q", "-rivers", rivers, src, dst});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  ASSERT_EQ(run_cli({"-q", src, plain}).exit_code, 0);
  const auto [x, y] = river_entry();
  const auto path = path_in_void(band_values(dst), x, y), plain_path = path_in_void(band_values(plain), x, y);
  EXPECT_GT(path.size(), 20u);
  EXPECT_EQ(near_river(path), static_cast<int>(path.size()));
  EXPECT_LT(near_river(plain_path), static_cast<int>(path.size()) / 2);  // the plane's own slope goes elsewhere
  // Known cells are kept bit for bit.
  const auto in = raw_band(src), out = raw_band(dst);
  for (std::size_t i = 0; i < in.size(); i += 2) {
    if (in[i] == 0x00 && in[i + 1] == 0x80) continue;  // -32768: a void
    ASSERT_EQ(in[i], out[i]);
    ASSERT_EQ(in[i + 1], out[i + 1]);
  }
}

TEST(CliMorphology, ARiverMaskOnTheRastersGridWorksLikeALine) {
  TempDir dir;
  const std::string src = dir.file("dem.tif"), dst = dir.file("out.tif"), mask = dir.file("river.tif");
  write_dem(src, plane);
  GDALDataset* m = GetGDALDriverManager()->GetDriverByName("GTiff")->Create(mask.c_str(), kW, kH, 1, GDT_Byte, nullptr);
  std::vector<std::uint8_t> v(static_cast<std::size_t>(kW) * kH, 0);
  const auto p = river_pixels();
  for (std::size_t k = 1; k < p.size(); ++k) {
    for (int s = 0; s <= 32; ++s) {
      const double t = s / 32.0;
      const int x = static_cast<int>(std::floor(p[k - 1].first + t * (p[k].first - p[k - 1].first)));
      const int y = static_cast<int>(std::floor(p[k - 1].second + t * (p[k].second - p[k - 1].second)));
      if (x >= 0 && y >= 0 && x < kW && y < kH) v[static_cast<std::size_t>(y) * kW + x] = 1;
    }
  }
  EXPECT_EQ(m->GetRasterBand(1)->RasterIO(GF_Write, 0, 0, kW, kH, v.data(), kW, kH, GDT_Byte, 0, 0, nullptr), CE_None);
  GDALClose(m);
  const RunResult r = run_cli({"-q", "-rivers", mask, src, dst});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto [x, y] = river_entry();
  const auto path = path_in_void(band_values(dst), x, y);
  EXPECT_GT(path.size(), 20u);
  EXPECT_GE(near_river(path), static_cast<int>(path.size()) - 1);
}

TEST(CliMorphology, LinesThatMissTheRasterWarnAndLeaveThePlainFill) {
  TempDir dir;
  const std::string src = dir.file("dem.tif"), dst = dir.file("out.tif"), plain = dir.file("plain.tif"),
                    rivers = dir.file("far.gpkg");
  write_dem(src, plane);
  write_lines(rivers, 32611, {{{5000.0, 5000.0}, {5100.0, 5300.0}}});
  const RunResult r = run_cli({"-q", "-rivers", rivers, src, dst});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("mcmd_fillnodata: warning:"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("do not cross the raster"), std::string::npos) << r.err;
  ASSERT_EQ(run_cli({"-q", src, plain}).exit_code, 0);
  EXPECT_EQ(raw_band(dst), raw_band(plain));
}

TEST(CliMorphology, BadLineFilesGetOneClearLine) {
  TempDir dir;
  const std::string src = dir.file("dem.tif"), dst = dir.file("out.tif"), points = dir.file("points.gpkg"),
                    junk = dir.file("junk.gpkg"), nocrs = dir.file("nocrs.gpkg");
  write_dem(src, plane);
  write_lines(points, 32611, {river_pixels()}, /*points=*/true);
  write_lines(nocrs, 32611, {river_pixels()}, false, /*with_crs=*/false);
  {
    FILE* f = std::fopen(junk.c_str(), "w");
    std::fputs("not a geopackage", f);
    std::fclose(f);
  }
  const struct {
    std::string file, expect;
  } cases[] = {{dir.file("missing.gpkg"), "cannot read the river lines"},
               {junk, "cannot read the river lines"},
               {points, "holds no line"},
               {nocrs, "CRS"}};  // GeoPackage calls a missing one "Undefined cartesian SRS"
  for (const auto& c : cases) {
    const RunResult r = run_cli({"-q", "-rivers", c.file, src, dst});
    EXPECT_EQ(r.exit_code, 1) << c.file;
    EXPECT_EQ(line_count(r.err), 1) << r.err;
    EXPECT_NE(r.err.find(c.expect), std::string::npos) << r.err;
    EXPECT_FALSE(file_exists(dst));
  }
  const RunResult r = run_cli({"-q", "-morph", "sometimes", src, dst});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("MORPH=sometimes is invalid"), std::string::npos) << r.err;
}

TEST(CliMorphology, MorphAutoCarriesTheGorgeThroughTheVoid) {
  // The core's test gorge (tests/core/morphology_test.cpp) as an Int16
  // GeoTIFF: a smooth fill dams it, -morph auto leaves no pond in the void.
  constexpr int w = 121, h = 161;
  const auto axis = [](double y) { return 60.0 + 8.0 * std::sin(y / 15.0); };
  const auto gorge = [&](int x, int y) { return 1000.0 - 0.5 * y + 80.0 * std::tanh(std::abs(x - axis(y)) / 5.0); };
  const auto hole = [&](int x, int y) { return std::hypot(x - axis(80), y - 80.0) <= 18; };
  TempDir dir;
  const std::string src = dir.file("dem.tif");
  GDALDataset* ds = GetGDALDriverManager()->GetDriverByName("GTiff")->Create(src.c_str(), w, h, 1, GDT_Float32, nullptr);
  std::vector<float> v(static_cast<std::size_t>(w) * h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) v[static_cast<std::size_t>(y) * w + x] = hole(x, y) ? -9999.0f : static_cast<float>(gorge(x, y));
  ds->GetRasterBand(1)->SetNoDataValue(-9999);
  EXPECT_EQ(ds->GetRasterBand(1)->RasterIO(GF_Write, 0, 0, w, h, v.data(), w, h, GDT_Float32, 0, 0, nullptr), CE_None);
  GDALClose(ds);
  const auto ponded = [&](const std::string& file) {  // void cells plain Priority-Flood raises by a centimetre
    const std::vector<double> z = band_values(file);
    const std::vector<morph::FlowCell> land(z.size(), morph::FlowCell::land);
    const std::vector<double> level = morph::flood_levels(z.data(), w, h, land.data());
    int n = 0;
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) n += hole(x, y) && level[static_cast<std::size_t>(y) * w + x] > z[static_cast<std::size_t>(y) * w + x] + 0.01;
    return n;
  };
  const std::string plain = dir.file("plain.tif"), morph = dir.file("morph.tif"), rough1 = dir.file("r1.tif"),
                    rough2 = dir.file("r2.tif");
  ASSERT_EQ(run_cli({"-q", src, plain}).exit_code, 0);
  const RunResult r = run_cli({"-q", "-morph", "auto", src, morph});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_GT(ponded(plain), 10);
  EXPECT_EQ(ponded(morph), 0);
  // With roughness too, and the same bits for any thread count.
  ASSERT_EQ(run_cli({"-q", "-morph", "auto", "-rs", "auto", "-threads", "1", src, rough1}).exit_code, 0);
  ASSERT_EQ(run_cli({"-q", "-morph", "auto", "-rs", "auto", "-threads", "2", src, rough2}).exit_code, 0);
  EXPECT_EQ(ponded(rough1), 0);
  EXPECT_EQ(raw_band(rough1), raw_band(rough2));
}

}  // namespace
}  // namespace mcmd::test
