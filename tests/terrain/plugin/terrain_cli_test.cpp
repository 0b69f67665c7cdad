// mcmd_terrain on real files: the sketch criteria (crests, a draining river,
// known cells bit for bit), from scratch, generators, georeferencing,
// supersampling, the same bits for any thread count.
#include <gtest/gtest.h>

#include <cmath>

#include "sketch_fixture.hpp"
#include "terrain_support.hpp"

namespace mcmd::test {
namespace {

void expect_ok(const RunResult& r) {
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(r.err.empty()) << r.err;
}

// The acceptance sketch: two ridges and a river in a 16-bit PNG, their
// states in a red/blue PNG, a rough terrain around them.
TEST(TerrainCli, SketchRidgesAreCrestsRiverDrainsKnownCellsExact) {
  TempDir dir;
  const int n = 513;
  write_test_sketch(dir.file("sketch.png"), dir.file("states.png"), n);
  const RunResult r = run_terrain({"-q", "-zrange", "0", "6553.5", "-states", dir.file("states.png"), "-rs", "150m",
                                   "-H", "0.85", "-seed", "3", "-hillshade", dir.file("shade.png"),
                                   dir.file("sketch.png"), dir.file("terrain.tif")});
  expect_ok(r);
  const Image z = read_image(dir.file("terrain.tif"));
  ASSERT_EQ(z.w, n);
  EXPECT_EQ(z.type, GDT_Float32);
  const auto at = [&](int x, int y) { return z.at(x, y); };
  const std::vector<SketchLine> lines = sketch_lines(n);
  const std::set<Cell> on_lines = all_cells(lines);
  for (int k = 0; k < 2; ++k) {
    const auto [maxima, profiles] = ridge_maxima(at, n, n, lines[k].cells, on_lines);
    EXPECT_GT(profiles, 300);
    EXPECT_GE(maxima, 0.9 * profiles) << "ridge " << k << ": " << maxima << " of " << profiles;
  }
  const std::vector<Cell>& river = lines[2].cells;
  const std::set<Cell> river_cells(river.begin(), river.end());
  const std::vector<Cell> path = d8_path(at, n, n, river.front());
  EXPECT_TRUE(on_border(path.back(), n, n));
  EXPECT_GT(path.size(), river.size() / 2);
  for (const Cell& c : path) EXPECT_TRUE(river_cells.count(c)) << "D8 leaves the river at " << c.first << "," << c.second;
  const Image sketch = read_image(dir.file("sketch.png"));
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      const double g = sketch.at(x, y);
      if (g == 65535) continue;
      ASSERT_EQ(z.at(x, y), static_cast<double>(static_cast<float>(0.0 + g * (6553.5 / 65535.0))));
    }
  const Image shade = read_image(dir.file("shade.png"));
  EXPECT_EQ(shade.w, n);
  EXPECT_EQ(shade.type, GDT_Byte);
}

// An 8-bit sketch as the paper's: white unknown, grey levels kept exactly,
// output Float32 (not 8-bit).
TEST(TerrainCli, ByteSketchWhiteIsUnknownGreyIsKept) {
  TempDir dir;
  Image img{64, 48, 1, GDT_Byte, std::vector<double>(64 * 48, 255.0)};
  for (int x = 5; x < 60; ++x) img.values[20 * 64 + x] = 100 + x;
  img.values[40 * 64 + 10] = 3;
  write_image(dir.file("s.png"), img, "PNG");
  expect_ok(run_terrain({"-q", "-rs", "0.2", dir.file("s.png"), dir.file("t.tif")}));
  const Image t = read_image(dir.file("t.tif"));
  EXPECT_EQ(t.type, GDT_Float32);
  for (int x = 5; x < 60; ++x) EXPECT_EQ(t.at(x, 20), 100 + x);
  EXPECT_EQ(t.at(10, 40), 3);
  bool fractional = false;
  for (double v : t.values) fractional |= v != std::floor(v);
  EXPECT_TRUE(fractional) << "an 8-bit terrain";
}

TEST(TerrainCli, FromScratchWithAnAbsoluteRoughness) {
  TempDir dir;
  expect_ok(run_terrain({"-q", "-size", "300", "200", "-rs", "300m", dir.file("t.tif")}));
  const Image t = read_image(dir.file("t.tif"));
  ASSERT_EQ(t.w, 300);
  ASSERT_EQ(t.h, 200);
  double lo = 1e300, hi = -1e300;
  for (double v : t.values) lo = std::min(lo, v), hi = std::max(hi, v);
  EXPECT_GT(hi - lo, 100);
}

// Erosion is on by default from scratch and around a skeleton, off for a
// sketch and points (-erode auto turns it on there), and -erode 0 is the
// synthesis alone.
TEST(TerrainCli, ErosionDefaults) {
  TempDir dir;
  const auto made = [&](std::vector<std::string> args, const std::string& name) {
    args.insert(args.begin(), "-q");
    args.push_back(dir.file(name));
    expect_ok(run_terrain(args));
    return raw_band(dir.file(name));
  };
  const std::vector<std::string> scratch = {"-size", "129", "129", "-rs", "300m"};
  const std::vector<std::string> skeleton = {"-size", "129", "129", "-skeleton", "-rs", "0.1"};
  const std::vector<std::string> points = {"-size", "65", "65", "-point", "0", "0", "500", "-point", "64", "64", "900",
                                           "-rs", "0.2"};
  for (const auto& [args, eroded] : {std::pair{scratch, true}, std::pair{skeleton, true}, std::pair{points, false}}) {
    std::vector<std::string> off = args;
    off.insert(off.end(), {"-erode", "0"});
    std::vector<std::string> on = args;
    on.insert(on.end(), {"-erode", "auto"});
    EXPECT_EQ(made(args, "default.tif") != made(off, "off.tif"), eroded) << args[3];
    EXPECT_NE(made(on, "on.tif"), made(off, "off.tif")) << args[3];
  }
}

// The paper's Fig. 2: corners at a medium elevation, the centre at the top.
TEST(TerrainCli, FivePointsAreKept) {
  TempDir dir;
  for (const char* method : {"mcmd", "paper-te", "paper-ds"}) {
    expect_ok(run_terrain({"-q", "-size", "129", "129", "-method", method, "-point", "0", "0", "500", "-point", "128",
                           "0", "500", "-point", "0", "128", "500", "-point", "128", "128", "500", "-point", "64",
                           "64", "1000", "-rs", "0.2", dir.file("t.tif")}));
    const Image t = read_image(dir.file("t.tif"));
    EXPECT_EQ(t.at(0, 0), 500) << method;
    EXPECT_EQ(t.at(128, 128), 500) << method;
    EXPECT_EQ(t.at(64, 64), 1000) << method;
  }
}

TEST(TerrainCli, SameBitsForAnyThreadCount) {
  TempDir dir;
  const std::vector<std::vector<std::string>> runs = {
      {"-size", "300", "257", "-rs", "200m"},
      {"-size", "257", "257", "-skeleton", "-rs", "0.4", "-seed", "2"},
      {"-size", "257", "200", "-skeleton", "-method", "paper-te", "-rs", "0.5", "-I", "1", "-Ibu", "6"},
      {"-size", "200", "200", "-rs", "100m", "-median", "5", "-median-passes", "2"}};
  for (const auto& run : runs) {
    std::vector<std::string> one = run, two = run;
    one.insert(one.end(), {"-q", "-threads", "1", dir.file("a.tif")});
    two.insert(two.end(), {"-q", "-threads", "2", dir.file("b.tif")});
    expect_ok(run_terrain(one));
    expect_ok(run_terrain(two));
    EXPECT_EQ(raw_band(dir.file("a.tif")), raw_band(dir.file("b.tif"))) << run[4];
  }
}

TEST(TerrainCli, SkeletonWithMethodNoneIsTheSkeletonDem) {
  TempDir dir;
  expect_ok(run_terrain({"-q", "-size", "257", "257", "-skeleton", "-method", "none", dir.file("s.tif")}));
  const Image s = read_image(dir.file("s.tif"));
  std::size_t known = 0, voids = 0;
  for (double v : s.values) (std::isnan(v) ? voids : known) += 1;
  EXPECT_GT(known, 200u);
  EXPECT_GT(voids, known * 10);
  // mcmd_fillnodata fills it (the NaN nodata marks the voids).
  ASSERT_EQ(run_cli({"-q", dir.file("s.tif"), dir.file("f.tif")}).exit_code, 0);
}

TEST(TerrainCli, GeoreferencingFromTheSketchAndOverrides) {
  TempDir dir;
  const std::array<double, 6> gt{500000, 30, 0, 4200000, 0, -30};
  Image img{33, 33, 1, GDT_Float32, std::vector<double>(33 * 33, -9999.0)};
  for (int k = 0; k < 33; ++k) img.values[k * 33 + k] = 100 + k;
  const double nodata = -9999;
  write_image(dir.file("s.tif"), img, "GTiff", 32611, &gt, &nodata);
  expect_ok(run_terrain({"-q", "-rs", "0.1", dir.file("s.tif"), dir.file("t.tif")}));
  GDALAllRegister();
  GDALDataset* t = GDALDataset::Open(dir.file("t.tif").c_str(), GDAL_OF_RASTER);
  double out[6];
  t->GetGeoTransform(out);
  for (int i = 0; i < 6; ++i) EXPECT_EQ(out[i], gt[i]);
  ASSERT_NE(t->GetSpatialRef(), nullptr);
  EXPECT_STREQ(t->GetSpatialRef()->GetAuthorityCode(nullptr), "32611");
  GDALClose(t);
  // Supersampled by 4: cell centres of the coarse grid are every 4th fine centre.
  expect_ok(run_terrain({"-q", "-upsample", "4", dir.file("s.tif"), dir.file("u.tif")}));
  t = GDALDataset::Open(dir.file("u.tif").c_str(), GDAL_OF_RASTER);
  t->GetGeoTransform(out);
  EXPECT_EQ(t->GetRasterXSize(), 129);
  EXPECT_DOUBLE_EQ(out[1], 7.5);
  EXPECT_DOUBLE_EQ(out[0] + 0.5 * out[1], gt[0] + 0.5 * gt[1]);
  GDALClose(t);
  const Image u = read_image(dir.file("u.tif"));
  for (int k = 0; k < 33; ++k) EXPECT_EQ(u.at(4 * k, 4 * k), 100 + k);
  // -a_ullr and -a_srs win; -like copies a template's.
  expect_ok(run_terrain({"-q", "-size", "100", "50", "-rs", "10m", "-a_ullr", "0", "50", "100", "0", "-a_srs",
                         "EPSG:4326", dir.file("g.tif")}));
  expect_ok(run_terrain({"-q", "-like", dir.file("g.tif"), "-rs", "10m", dir.file("l.tif")}));
  t = GDALDataset::Open(dir.file("l.tif").c_str(), GDAL_OF_RASTER);
  t->GetGeoTransform(out);
  EXPECT_EQ(t->GetRasterXSize(), 100);
  EXPECT_EQ(out[1], 1.0);
  EXPECT_EQ(out[5], -1.0);
  EXPECT_STREQ(t->GetSpatialRef()->GetAuthorityCode(nullptr), "4326");
  GDALClose(t);
}

TEST(TerrainCli, PeaksAndOutputTypes) {
  TempDir dir;
  expect_ok(run_terrain({"-q", "-size", "101", "101", "-peaks", "iizuka", "-ot", "Int16", dir.file("p.tif")}));
  const Image p = read_image(dir.file("p.tif"));
  EXPECT_EQ(p.type, GDT_Int16);
  EXPECT_EQ(p.at(20, 50), std::round(p.at(20, 50)));
  EXPECT_GT(p.at(20, 50), 100);  // peak (5) of Table 1
  expect_ok(run_terrain({"-q", "-size", "129", "129", "-peaks", "iizuka", "-upsample", "8", "-zrange", "0", "1000",
                         "-rs", "20m", dir.file("u.tif")}));
  EXPECT_EQ(read_image(dir.file("u.tif")).w, 129);
}

TEST(TerrainCli, ProgressAndHelp) {
  TempDir dir;
  const RunResult r = run_terrain({"-size", "65", "65", "-rs", "10m", dir.file("t.tif")});
  expect_ok(r);
  EXPECT_NE(r.out.find("100 - done"), std::string::npos);
  const RunResult help = run_terrain({"--help"});
  ASSERT_EQ(help.exit_code, 0);
  for (const char* flag : {"-size", "-like", "-a_ullr", "-a_srs", "-ot", "-of", "-co", "-a_nodata", "-hillshade", "-q",
                           "-b", "-unknown", "-zrange", "-states", "-point", "-upsample", "-skeleton",
                           "-ridge-couples", "-river-particles", "-peaks", "-peaks-noise", "-peaks-threshold",
                           "-method", "-scheme", "-rs", "-H", "-rt", "-seed", "-sharpness", "-I", "-Ibu", "-ridge-I",
                           "-river-Ibu", "-delta", "-threads", "-o", "-median", "-median-passes", "-median-all",
                           "--version"})
    EXPECT_NE(help.out.find(std::string(flag) + " "), std::string::npos) << flag;
  EXPECT_EQ(run_terrain({"--version"}).out.rfind("mcmd_terrain ", 0), 0u);
}

// The README's first example: t.png and t.tif share the stem, and each is
// written in its own temporary folder, both moved into place.
TEST(TerrainCli, HillshadeBesideATerrainOfTheSameStem) {
  TempDir dir;
  expect_ok(run_terrain({"-q", "-size", "65", "65", "-rs", "300m", "-seed", "4", "-hillshade", dir.file("t.png"),
                         dir.file("t.tif")}));
  EXPECT_EQ(dir.listing(), (std::vector<std::string>{"t.png", "t.tif"}));
  EXPECT_EQ(read_image(dir.file("t.png")).w, 65);
  EXPECT_EQ(read_image(dir.file("t.tif")).w, 65);
}

// Semivariance at lag 1 (row and column pairs): the roughness at the finest scale.
double gamma1(const Image& z) {
  double sum = 0, n = 0;
  for (int y = 0; y + 1 < z.h; ++y)
    for (int x = 0; x + 1 < z.w; ++x) {
      const double dx = z.at(x + 1, y) - z.at(x, y), dy = z.at(x, y + 1) - z.at(x, y);
      sum += dx * dx + dy * dy, n += 2;
    }
  return 0.5 * sum / n;
}

// -upsample 4 -rs auto: the detail made between a DEM's cells continues its
// roughness. A real-looking terrain's every 4th cell, supersampled again, has
// about the original's roughness at the finest scale, nearer than with -rs 0
// (too smooth); the same bits on one thread.
TEST(TerrainCli, UpsampleWithRsAutoMeasuresTheDem) {
  TempDir dir;
  const Image truth = read_image(std::string(MCMD_TESTDATA_DIR) + "/sample_truth.tif");
  ASSERT_EQ(truth.w, 257);
  Image coarse{65, 65, 1, GDT_Float32, {}};
  for (int y = 0; y < 65; ++y)
    for (int x = 0; x < 65; ++x) coarse.values.push_back(truth.at(4 * x, 4 * y));
  write_image(dir.file("coarse.tif"), coarse, "GTiff");
  expect_ok(run_terrain({"-q", "-upsample", "4", "-rs", "auto", dir.file("coarse.tif"), dir.file("auto.tif")}));
  expect_ok(run_terrain({"-q", "-upsample", "4", dir.file("coarse.tif"), dir.file("smooth.tif")}));
  expect_ok(run_terrain({"-q", "-threads", "1", "-upsample", "4", "-rs", "auto", dir.file("coarse.tif"),
                         dir.file("one.tif")}));
  EXPECT_EQ(raw_band(dir.file("auto.tif")), raw_band(dir.file("one.tif")));
  const Image rough = read_image(dir.file("auto.tif")), smooth = read_image(dir.file("smooth.tif"));
  for (int y = 0; y < 65; ++y)
    for (int x = 0; x < 65; ++x) ASSERT_EQ(rough.at(4 * x, 4 * y), truth.at(4 * x, 4 * y));
  const double real = gamma1(truth), made = gamma1(rough);
  EXPECT_GT(made, 0.75 * real) << made << " against " << real;
  EXPECT_LT(made, 1.33 * real) << made << " against " << real;
  EXPECT_LT(std::fabs(std::log(made / real)), std::fabs(std::log(gamma1(smooth) / real)));
}

// A DEM with a lake (a flat of zero residual) beside its relief: -rs auto's
// local roughness there is 0, summed to a hair below it, and once gave NaN.
TEST(TerrainCli, UpsampleWithRsAutoOverALake) {
  TempDir dir;
  const Image truth = read_image(std::string(MCMD_TESTDATA_DIR) + "/sample_truth.tif");
  Image coarse{257, 257, 1, GDT_Float32, {}};
  for (int y = 0; y < 257; ++y)
    for (int x = 0; x < 257; ++x)
      coarse.values.push_back(x > 100 && y > 100 && x < 200 && y < 200 ? 6122.5 : 10 * truth.at(x, y));
  write_image(dir.file("coarse.tif"), coarse, "GTiff");
  expect_ok(run_terrain({"-q", "-upsample", "4", "-rs", "auto", dir.file("coarse.tif"), dir.file("auto.tif")}));
  const Image t = read_image(dir.file("auto.tif"));
  for (const double v : t.values) ASSERT_TRUE(std::isfinite(v));
  EXPECT_EQ(t.at(600, 600), 6122.5f);
}

// -rs auto around a dense sketch: a 64-cell hole in the real-looking terrain
// is made about as rough as the terrain it replaced; known cells exact.
TEST(TerrainCli, RsAutoAroundADenseSketch) {
  TempDir dir;
  const Image truth = read_image(std::string(MCMD_TESTDATA_DIR) + "/sample_truth.tif");
  Image sketch{truth.w, truth.h, 1, GDT_Float32, truth.values};
  for (int y = 96; y < 160; ++y)
    for (int x = 96; x < 160; ++x) sketch.values[static_cast<std::size_t>(y) * truth.w + x] = -9999;
  const double nodata = -9999;
  write_image(dir.file("sketch.tif"), sketch, "GTiff", 0, nullptr, &nodata);
  expect_ok(run_terrain({"-q", "-rs", "auto", dir.file("sketch.tif"), dir.file("t.tif")}));
  const Image t = read_image(dir.file("t.tif"));
  const auto hole = [](const Image& z) {
    Image part{56, 56, 1, GDT_Float64, {}};
    for (int y = 100; y < 156; ++y)
      for (int x = 100; x < 156; ++x) part.values.push_back(z.at(x, y));
    return part;
  };
  const double real = gamma1(hole(truth)), made = gamma1(hole(t));
  EXPECT_GT(made, 0.5 * real) << made << " against " << real;
  EXPECT_LT(made, 2.5 * real) << made << " against " << real;
  for (std::size_t i = 0; i < sketch.values.size(); ++i) {
    if (sketch.values[i] == nodata) continue;
    ASSERT_EQ(t.values[i], truth.values[i]);
  }
}

// -rs in elevation units in mcmd_fillnodata: a flat rim (range 0) gets relief
// with -rs 20m, none with a fraction of its range.
TEST(TerrainCli, FillnodataTakesRsInElevationUnits) {
  TempDir dir;
  Image img{64, 64, 1, GDT_Float32, std::vector<double>(64 * 64, 250.0)};
  for (int y = 16; y < 48; ++y)
    for (int x = 16; x < 48; ++x) img.values[y * 64 + x] = -9999;
  const double nodata = -9999;
  write_image(dir.file("flat.tif"), img, "GTiff", 0, nullptr, &nodata);
  ASSERT_EQ(run_cli({"-q", "-rs", "0.3", dir.file("flat.tif"), dir.file("a.tif")}).exit_code, 0);
  ASSERT_EQ(run_cli({"-q", "-rs", "20m", dir.file("flat.tif"), dir.file("b.tif")}).exit_code, 0);
  ASSERT_EQ(run_cli({"-q", "-method", "paper-ds", "-rs", "20m", dir.file("flat.tif"), dir.file("c.tif")}).exit_code, 0);
  const Image a = read_image(dir.file("a.tif")), b = read_image(dir.file("b.tif")), c = read_image(dir.file("c.tif"));
  double spread_a = 0, spread_b = 0, spread_c = 0;
  for (std::size_t i = 0; i < a.values.size(); ++i) {
    spread_a = std::max(spread_a, std::fabs(a.values[i] - 250));
    spread_b = std::max(spread_b, std::fabs(b.values[i] - 250));
    spread_c = std::max(spread_c, std::fabs(c.values[i] - 250));
  }
  EXPECT_LT(spread_a, 1e-3);
  EXPECT_GT(spread_b, 2.0);
  EXPECT_GT(spread_c, 0.01);  // the paper's displacement shrinks fast at the void's deep levels
}

}  // namespace
}  // namespace mcmd::test

namespace mcmd::test {
namespace {

// -unknown black and a one-band states raster (1 = ridge): the black cells
// are made, the marked cells become creased ridges (the terrain changes),
// and every known cell stays.
TEST(TerrainCli, UnknownBlackAndOneBandStates) {
  TempDir dir;
  Image img{80, 60, 1, GDT_Byte, std::vector<double>(80 * 60, 0.0)};
  Image states{80, 60, 1, GDT_Byte, std::vector<double>(80 * 60, 0.0)};
  for (int x = 10; x < 70; ++x) {
    img.values[30 * 80 + x] = 200;
    states.values[30 * 80 + x] = 1;
  }
  img.values[5 * 80 + 5] = 20;
  img.values[55 * 80 + 75] = 20;
  write_image(dir.file("s.tif"), img, "GTiff");
  write_image(dir.file("states.tif"), states, "GTiff");
  expect_ok(run_terrain({"-q", "-unknown", "black", dir.file("s.tif"), dir.file("plain.tif")}));
  expect_ok(run_terrain({"-q", "-unknown", "black", "-states", dir.file("states.tif"), dir.file("s.tif"),
                         dir.file("ridge.tif")}));
  const Image plain = read_image(dir.file("plain.tif")), ridge = read_image(dir.file("ridge.tif"));
  for (int x = 10; x < 70; ++x) {
    EXPECT_EQ(plain.at(x, 30), 200);
    EXPECT_EQ(ridge.at(x, 30), 200);
  }
  EXPECT_EQ(ridge.at(5, 5), 20);
  EXPECT_NE(plain.values, ridge.values);
  // The crest: two cells off the ridge the creased terrain is lower than the plain one.
  EXPECT_LT(ridge.at(40, 28), plain.at(40, 28));
  EXPECT_LT(ridge.at(40, 32), plain.at(40, 32));
  EXPECT_GT(plain.at(40, 40), 20);  // black (0) cells were made, not kept
}

}  // namespace
}  // namespace mcmd::test
