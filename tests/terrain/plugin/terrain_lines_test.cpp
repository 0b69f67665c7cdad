// -ridges and -rivers: vector lines (reprojected) and raster masks make
// crests and a draining valley; bad line files give one line.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <iomanip>

#include "ogr_spatialref.h"
#include "sketch_fixture.hpp"
#include "terrain_support.hpp"

namespace mcmd::test {
namespace {

constexpr int kN = 513;
constexpr double kX0 = 500000, kY0 = 4200000, kCell = 30;  // EPSG:32611

// The fixture's lines (in cell centres) as GeoJSON LineStrings in EPSG:4326.
void write_lines_4326(const std::string& path, bool rivers) {
  OGRSpatialReference utm, wgs;
  utm.importFromEPSG(32611);
  wgs.importFromEPSG(4326);
  wgs.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
  OGRCoordinateTransformation* ct = OGRCreateCoordinateTransformation(&utm, &wgs);
  std::ofstream out(path);
  out << R"({"type":"FeatureCollection","features":[)";
  bool first = true;
  for (const SketchLine& l : sketch_lines(kN)) {
    if (l.river != rivers) continue;
    out << (first ? "" : ",") << R"({"type":"Feature","properties":{},"geometry":{"type":"LineString","coordinates":[)";
    first = false;
    for (std::size_t k = 0; k < l.cells.size(); k += 8) {
      double x = kX0 + kCell * (l.cells[k].first + 0.5), y = kY0 - kCell * (l.cells[k].second + 0.5);
      ct->Transform(1, &x, &y);
      out << (k ? "," : "") << "[" << std::setprecision(12) << x << "," << y << "]";
    }
    const Cell end = l.cells.back();
    double x = kX0 + kCell * (end.first + 0.5), y = kY0 - kCell * (end.second + 0.5);
    ct->Transform(1, &x, &y);
    out << ",[" << std::setprecision(12) << x << "," << y << "]]}}";
  }
  out << "]}\n";
  OGRCoordinateTransformation::DestroyCT(ct);
}

double distance_to(const std::vector<Cell>& line, Cell c) {
  double best = 1e300;
  for (const Cell& p : line) best = std::min(best, std::hypot(p.first - c.first, p.second - c.second));
  return best;
}

void check_crests_and_valley(const Image& z) {
  const auto at = [&](int x, int y) { return z.at(x, y); };
  const std::vector<SketchLine> lines = sketch_lines(kN);
  const std::set<Cell> near_lines = [&] {
    std::set<Cell> s;
    for (const SketchLine& l : lines)
      for (const Cell& c : l.cells)
        for (int d = -1; d <= 1; ++d) s.insert({c.first, c.second + d});  // traced cells may sit a cell off
    return s;
  }();
  for (int k = 0; k < 2; ++k) {
    // The traced ridge may run a cell beside the fixture's: take the highest of the cell and its neighbours across.
    const auto crest = [&](int x, int y) { return std::max({at(x, y), at(x, std::max(0, y - 1)), at(x, std::min(kN - 1, y + 1))}); };
    int maxima = 0, profiles = 0;  // profiles 2.5 cells out: beyond the one-cell slack
    const std::vector<Cell>& cells = lines[k].cells;
    for (std::size_t i = 2; i + 2 < cells.size(); ++i) {
      const auto [x, y] = cells[i];
      const double dx = cells[i + 2].first - cells[i - 2].first, dy = cells[i + 2].second - cells[i - 2].second;
      const double L = std::hypot(dx, dy);
      const int ax = static_cast<int>(std::lround(x - 2.5 * dy / L)), ay = static_cast<int>(std::lround(y + 2.5 * dx / L));
      const int bx = static_cast<int>(std::lround(x + 2.5 * dy / L)), by = static_cast<int>(std::lround(y - 2.5 * dx / L));
      if (ax < 0 || bx < 0 || ay < 0 || by < 0 || ax >= kN || bx >= kN || ay >= kN || by >= kN) continue;
      if (near_lines.count({ax, ay}) || near_lines.count({bx, by})) continue;
      ++profiles;
      maxima += crest(x, y) > at(ax, ay) && crest(x, y) > at(bx, by);
    }
    EXPECT_GT(profiles, 300);
    EXPECT_GE(maxima, 0.9 * profiles) << "ridge " << k;
  }
  const std::vector<Cell>& river = lines[2].cells;
  const std::vector<Cell> path = d8_path(at, kN, kN, river.front());
  EXPECT_TRUE(on_border(path.back(), kN, kN));
  for (const Cell& c : path) EXPECT_LE(distance_to(river, c), 1.5) << c.first << "," << c.second;
}

std::vector<std::string> georef() {
  return {"-q", "-size", "513", "513", "-a_srs", "EPSG:32611", "-a_ullr", "500000", "4200000", "515390", "4184610",
          "-rs", "150m", "-H", "0.85", "-ridge-z", "900", "-river-z", "480,80"};
}

TEST(TerrainLines, VectorLinesInAnotherCrsMakeCrestsAndADrainingValley) {
  TempDir dir;
  write_lines_4326(dir.file("ridges.geojson"), false);
  write_lines_4326(dir.file("rivers.geojson"), true);
  std::vector<std::string> args = georef();
  args.insert(args.end(), {"-ridges", dir.file("ridges.geojson"), "-rivers", dir.file("rivers.geojson"),
                           dir.file("t.tif")});
  const RunResult r = run_terrain(args);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  check_crests_and_valley(read_image(dir.file("t.tif")));
}

TEST(TerrainLines, RasterMasksWork) {
  TempDir dir;
  for (const bool rivers : {false, true}) {
    Image mask{kN, kN, 1, GDT_Byte, std::vector<double>(static_cast<std::size_t>(kN) * kN, 0.0)};
    for (const SketchLine& l : sketch_lines(kN))
      if (l.river == rivers)
        for (const Cell& c : l.cells) mask.values[static_cast<std::size_t>(c.second) * kN + c.first] = 1;
    write_image(dir.file(rivers ? "rivers.tif" : "ridges.tif"), mask, "GTiff");
  }
  std::vector<std::string> args = georef();
  args.erase(args.begin() + 4, args.begin() + 11);  // no georeferencing: the masks are on the grid
  args.insert(args.end(), {"-ridges", dir.file("ridges.tif"), "-rivers", dir.file("rivers.tif"), dir.file("t.tif")});
  const RunResult r = run_terrain(args);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  check_crests_and_valley(read_image(dir.file("t.tif")));
}

TEST(TerrainLines, BadLineFilesGiveOneLine) {
  TempDir dir;
  std::ofstream(dir.file("nocrs.csv")) << "id,WKT\n1,\"LINESTRING (501000 4190000,510000 4191000)\"\n";
  std::ofstream(dir.file("far.geojson"))
      << R"({"type":"FeatureCollection","features":[{"type":"Feature","properties":{},)"
      << R"("geometry":{"type":"LineString","coordinates":[[10,50],[11,51]]}}]})";
  std::ofstream(dir.file("junk.geojson")) << "not json";
  Image small{9, 9, 1, GDT_Byte, std::vector<double>(81, 1.0)};
  write_image(dir.file("small_mask.tif"), small, "GTiff");
  const struct {
    const char* file;
    const char* message;
  } cases[] = {{"nocrs.csv", "have no coordinate reference system"},
               {"far.geojson", "crosses the 513x513 raster"},
               {"junk.geojson", "cannot read the river lines"},
               {"missing.gpkg", "cannot read the river lines"},
               {"small_mask.tif", "is 9x9 but the raster is 513x513"}};
  for (const auto& c : cases) {
    std::vector<std::string> args = georef();
    args.insert(args.end(), {"-rivers", dir.file(c.file), dir.file("t.tif")});
    const auto before = dir.listing();
    const RunResult r = run_terrain(args);
    EXPECT_NE(r.exit_code, 0) << c.file;
    EXPECT_EQ(line_count(r.err), 1) << r.err;
    EXPECT_EQ(r.err.rfind("mcmd_terrain: error: ", 0), 0u) << r.err;
    EXPECT_NE(r.err.find(c.message), std::string::npos) << c.file << ": " << r.err;
    EXPECT_EQ(dir.listing(), before);
  }
  // A line without heights over unknown cells.
  std::vector<std::string> args = {"-q", "-size", "64", "64", "-rs", "10m", "-rivers", dir.file("small_mask.tif"),
                                   dir.file("t.tif")};
  Image mask{64, 64, 1, GDT_Byte, std::vector<double>(64 * 64, 0.0)};
  for (int x = 0; x < 64; ++x) mask.values[32 * 64 + x] = 1;
  write_image(dir.file("small_mask.tif"), mask, "GTiff");
  const RunResult r = run_terrain(args);
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.err.find("give -river-z"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace mcmd::test
