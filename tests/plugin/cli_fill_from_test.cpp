// -fill-from (the delta surface fill, mcmd/delta_fill.hpp) through the real
// mcmd_fillnodata: a second DEM in another CRS and resolution, one that
// covers part of the voids, one with voids of its own, one of another type,
// and the errors.
#include <cmath>
#include <gtest/gtest.h>

#include "gdal_utils.h"
#include "test_support.hpp"

namespace mcmd::test {
namespace {

constexpr double kNodata = -9999.0;

RasterSpec spec(bool voids) {
  RasterSpec s;
  s.type = GDT_Float32;
  s.width = 160;
  s.height = 120;
  s.nodata = kNodata;
  s.voids = voids;
  s.scale = 400.0;
  return s;
}

// gdalwarp of `src` into `dst` with these arguments.
void warp(const std::string& src, const std::string& dst, const std::vector<std::string>& args) {
  CPLStringList list;
  for (const std::string& a : args) list.AddString(a.c_str());
  GDALWarpAppOptions* options = GDALWarpAppOptionsNew(list.List(), nullptr);
  GDALDatasetH in = GDALOpen(src.c_str(), GA_ReadOnly);
  ASSERT_NE(in, nullptr);
  GDALDatasetH out = GDALWarp(dst.c_str(), nullptr, 1, &in, options, nullptr);
  GDALWarpAppOptionsFree(options);
  ASSERT_NE(out, nullptr);
  GDALClose(out);
  GDALClose(in);
}

double rmse_on_voids(const std::vector<double>& filled, const std::vector<double>& truth,
                     const std::vector<double>& voided) {
  double sum = 0;
  std::size_t n = 0;
  for (std::size_t i = 0; i < voided.size(); ++i)
    if (voided[i] == kNodata) sum += (filled[i] - truth[i]) * (filled[i] - truth[i]), ++n;
  return std::sqrt(sum / n);
}

struct Files {
  TempDir dir;
  std::string src = dir.file("src.tif"), truth = dir.file("truth.tif");
  Files() {
    make_raster(src, spec(true));
    make_raster(truth, spec(false));
  }
};

TEST(CliFillFrom, ASecondDemInAnotherCrsAndResolutionBeatsThePlainFill) {
  Files f;
  // The truth, 4 times coarser, in geographic coordinates, as Int16.
  const std::string second = f.dir.file("second_4326.tif");
  warp(f.truth, second, {"-t_srs", "EPSG:4326", "-r", "average", "-ts", "40", "30", "-ot", "Int16"});
  const std::string plain = f.dir.file("plain.tif"), from = f.dir.file("from.tif");
  ASSERT_EQ(run_cli({"-q", f.src, plain}).exit_code, 0);
  const RunResult r = run_cli({"-q", "-fill-from", second, f.src, from});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto in = band_values(f.src), truth = band_values(f.truth), out = band_values(from);
  for (std::size_t i = 0; i < in.size(); ++i) {
    if (in[i] != kNodata) {
      ASSERT_EQ(out[i], in[i]) << "valid cell changed at " << i;
    }
    ASSERT_NE(out[i], kNodata) << "void left at " << i;
  }
  const double with = rmse_on_voids(out, truth, in), without = rmse_on_voids(band_values(plain), truth, in);
  EXPECT_LT(with, 0.8 * without) << with << " against the plain fill's " << without;
}

TEST(CliFillFrom, VoidsTheSecondDemDoesNotCoverGetThePlainFill) {
  Files f;
  // Part of the raster only (its left 70 columns), and a hole of its own.
  const std::string part = f.dir.file("part.tif"), holed = f.dir.file("holed.tif");
  warp(f.truth, part, {"-te", "350000", "4106400", "352100", "4110000", "-tr", "60", "60", "-r", "average"});
  warp(part, holed, {"-dstnodata", "-1"});
  {
    GDALDataset* ds = GDALDataset::Open(holed.c_str(), GDAL_OF_RASTER | GDAL_OF_UPDATE);
    ASSERT_NE(ds, nullptr);
    std::vector<float> hole(8 * 8, -1.0f);
    ASSERT_EQ(ds->GetRasterBand(1)->RasterIO(GF_Write, 10, 15, 8, 8, hole.data(), 8, 8, GDT_Float32, 0, 0, nullptr),
              CE_None);
    GDALClose(ds);
  }
  const std::string plain = f.dir.file("plain.tif"), from = f.dir.file("from.tif");
  ASSERT_EQ(run_cli({"-q", f.src, plain}).exit_code, 0);
  const RunResult r = run_cli({"-q", "-fill-from", holed, "-o", "FILL_FROM_RESAMPLING=bilinear", f.src, from});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto in = band_values(f.src), a = band_values(plain), b = band_values(from);
  std::size_t same = 0, changed = 0;
  for (std::size_t i = 0; i < in.size(); ++i) {
    if (in[i] != kNodata) continue;
    const int x = static_cast<int>(i % 160), y = static_cast<int>(i / 160);
    const bool covered = x < 68 && !(x >= 19 && x < 37 && y >= 29 && y < 47);  // away from the edge and the hole
    const bool uncovered = x >= 72 || (x >= 21 && x < 35 && y >= 31 && y < 45);
    ASSERT_NE(b[i], kNodata);
    if (uncovered) {
      ASSERT_EQ(b[i], a[i]) << "not the plain fill at " << x << "," << y;
      ++same;
    }
    if (covered && b[i] != a[i]) ++changed;
  }
  EXPECT_GT(same, 100u);
  EXPECT_GT(changed, 100u);
}

TEST(CliFillFrom, SameBytesForAnyThreadCountAndTiles) {
  Files f;
  const std::string second = f.dir.file("second.tif");
  warp(f.truth, second, {"-tr", "120", "120", "-r", "average"});
  std::vector<unsigned char> first;
  for (const char* threads : {"1", "2"}) {
    const std::string out = f.dir.file(std::string("t") + threads + ".tif");
    const RunResult r = run_cli({"-q", "-fill-from", second, "-tile", "33", "-o", "TILING=ALWAYS", "-rs", "auto",
                                 "-threads", threads, f.src, out});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    if (first.empty()) first = raw_band(out);
    EXPECT_EQ(raw_band(out), first);
  }
}

TEST(CliFillFrom, ErrorsAreOneLineAndLeaveNothing) {
  Files f;
  const std::string far = f.dir.file("far.tif");
  warp(f.truth, far, {"-t_srs", "EPSG:32611", "-te", "900000", "4000000", "904800", "4003600", "-ts", "40", "30"});
  const std::string src_bytes = file_bytes(f.src);
  struct Case {
    std::vector<std::string> args;
    std::string expect;
  };
  const Case cases[] = {
      {{"-fill-from", far}, "does not overlap the raster"},
      {{"-fill-from", f.dir.file("missing.tif")}, "cannot be opened as a raster"},
      {{"-fill-from", far, "-morph", "auto"}, "do not combine"},
      {{"-fill-from", far, "-o", "FILL_FROM_RESAMPLING=nearest"}, "FILL_FROM_RESAMPLING=nearest"},
  };
  for (const Case& c : cases) {
    const std::vector<std::string> listing = f.dir.listing();
    std::vector<std::string> args = {"-q"};
    args.insert(args.end(), c.args.begin(), c.args.end());
    args.push_back(f.src);
    args.push_back(f.dir.file("out.tif"));
    expect_clean_failure(run_cli(args), c.expect, f.dir, listing, f.src, src_bytes);
  }
}

}  // namespace
}  // namespace mcmd::test

namespace mcmd::test {
namespace {

// With -rs, the relief is added on top of the delta surface, not faded with
// the differences: rough minus smooth is the plain fill's relief, deep inside
// the void too.
TEST(CliFillFrom, RoughnessIsNotFadedAwayFromTheRim) {
  Files f;
  const std::string second = f.dir.file("second.tif");
  warp(f.truth, second, {"-tr", "300", "300", "-r", "average"});
  const auto run = [&](const std::vector<std::string>& extra, const std::string& name) {
    std::vector<std::string> args = {"-q"};
    args.insert(args.end(), extra.begin(), extra.end());
    args.push_back(f.src);
    args.push_back(f.dir.file(name));
    const RunResult r = run_cli(args);
    EXPECT_EQ(r.exit_code, 0) << r.err;
    return band_values(f.dir.file(name));
  };
  const auto ff = run({"-fill-from", second}, "ff.tif"), ff_rough = run({"-fill-from", second, "-rs", "0.1"}, "ffr.tif");
  const auto plain = run({}, "p.tif"), plain_rough = run({"-rs", "0.1"}, "pr.tif");
  // The blob's centre cells (the blob: centre 56,48, radius 21.6).
  double sxy = 0, sxx = 0, syy = 0;
  std::size_t n = 0;
  for (int y = 38; y < 58; ++y)
    for (int x = 46; x < 66; ++x) {
      const std::size_t i = static_cast<std::size_t>(y) * 160 + x;
      const double a = ff_rough[i] - ff[i], b = plain_rough[i] - plain[i];
      sxy += a * b, sxx += a * a, syy += b * b, ++n;
    }
  ASSERT_GT(std::sqrt(syy / n), 1.0);  // the plain fill's relief there, in metres
  EXPECT_GT(sxy / std::sqrt(sxx * syy), 0.9);
  EXPECT_NEAR(std::sqrt(sxx / n), std::sqrt(syy / n), 0.2 * std::sqrt(syy / n));
}

}  // namespace
}  // namespace mcmd::test
