// The CLI through the tiled engine: thread determinism, tile sizes, in-place
// versus copy, and formats written from a work file.
#include <cmath>
#include <gtest/gtest.h>
#include <string>
#include <vector>

#include "test_support.hpp"

using namespace mcmd::test;

namespace {

// A raster large enough for many 33- and 65-cell tiles, voids across seams.
std::string make_tiled_source(const TempDir& dir) {
  RasterSpec spec;
  spec.type = GDT_Float32;
  spec.nodata = -9999.0;
  spec.width = 301;
  spec.height = 203;
  spec.scale = 800.0;
  const std::string src = dir.file("src.tif");
  make_raster(src, spec);
  return src;
}

double rmse(const std::vector<double>& a, const std::vector<double>& truth, const std::vector<double>& voided,
            double nodata) {
  double se = 0.0;
  std::size_t n = 0;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (voided[i] == nodata) {
      se += (a[i] - truth[i]) * (a[i] - truth[i]);
      ++n;
    }
  return n ? std::sqrt(se / static_cast<double>(n)) : 0.0;
}

}  // namespace

TEST(CliTiling, ThreadCountDoesNotChangeOneBit) {
  TempDir dir;
  const std::string src = make_tiled_source(dir);
  for (const char* tile : {"33", "0"}) {
    const std::string a = dir.file("a.tif"), b = dir.file("b.tif");
    ASSERT_EQ(run_cli({"-q", "-o", "TILING=ALWAYS", "-tile", tile, "-threads", "1", src, a}).exit_code, 0);
    ASSERT_EQ(run_cli({"-q", "-o", "TILING=ALWAYS", "-tile", tile, "-threads", "2", src, b}).exit_code, 0);
    EXPECT_EQ(raw_band(a), raw_band(b)) << "tile " << tile;
    EXPECT_EQ(file_bytes(a), file_bytes(b)) << "tile " << tile;
  }
}

// A small raster is filled whole (docs/tiling.md, "Small rasters"): -tile is
// the size used when tiling, so alone it changes nothing; TILING=ALWAYS tiles.
TEST(CliTiling, SmallRasterIsFilledWholeWhateverTheTileSize) {
  TempDir dir;
  const std::string src = make_tiled_source(dir);
  const std::string plain = dir.file("plain.tif"), t257 = dir.file("t257.tif"), t65 = dir.file("t65.tif");
  ASSERT_EQ(run_cli({"-q", src, plain}).exit_code, 0);
  ASSERT_EQ(run_cli({"-q", "-tile", "257", "-threads", "1", src, t257}).exit_code, 0);
  ASSERT_EQ(run_cli({"-q", "-o", "TILING=ALWAYS", "-tile", "65", src, t65}).exit_code, 0);
  EXPECT_EQ(raw_band(plain), raw_band(t257));
  EXPECT_NE(raw_band(plain), raw_band(t65));
}

TEST(CliTiling, TileSizesFillTestdataCompletelyAndAlike) {
  const std::string src = std::string(MCMD_TESTDATA_DIR) + "/peaks_int16_geo.tif";
  const std::string truth = std::string(MCMD_TESTDATA_DIR) + "/peaks_truth_float32.tif";
  if (!file_exists(src) || !file_exists(truth)) GTEST_SKIP() << "testdata missing";
  TempDir dir;
  const std::vector<double> in = band_values(src), t = band_values(truth);
  std::vector<double> errors;
  for (const char* tile : {"257", "33", "17"}) {
    const std::string out = dir.file(std::string("t") + tile + ".tif");
    const RunResult r = run_cli({"-q", "-o", "TILING=ALWAYS", "-tile", tile, src, out});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const std::vector<double> v = band_values(out);
    for (std::size_t i = 0; i < v.size(); ++i) {
      ASSERT_NE(v[i], -32768.0) << "unfilled cell with -tile " << tile;
      if (in[i] != -32768.0) {
        ASSERT_EQ(v[i], in[i]) << "known cell changed with -tile " << tile;
      }
    }
    errors.push_back(rmse(v, t, in, -32768.0));
  }
  EXPECT_LT(errors[0], 50.0);  // the peaks terrain spans about 500 m
  EXPECT_NEAR(errors[1], errors[0], 0.1 * errors[0] + 0.5) << errors[0] << " vs " << errors[1];
  EXPECT_NEAR(errors[2], errors[0], 0.1 * errors[0] + 0.5) << errors[0] << " vs " << errors[2];
}

TEST(CliTiling, InPlaceEqualsCopyAcrossManyTiles) {
  TempDir dir;
  const std::string src = make_tiled_source(dir);
  const std::string copy = dir.file("copy.tif"), inplace = dir.file("inplace.tif");
  copy_file(src, inplace);
  ASSERT_EQ(run_cli({"-q", "-o", "TILING=ALWAYS", "-tile", "33", src, copy}).exit_code, 0);
  const RunResult r = run_cli({"-q", "-o", "TILING=ALWAYS", "-tile", "33", inplace});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(raw_band(inplace), raw_band(copy));
}

TEST(CliTiling, CompressedAndCogOutputsMatchThePlainOne) {
  TempDir dir;
  const std::string src = make_tiled_source(dir);
  const std::string plain = dir.file("plain.tif"), deflate = dir.file("deflate.tif"), cog = dir.file("cog.tif");
  ASSERT_EQ(run_cli({"-q", "-o", "TILING=ALWAYS", "-tile", "65", src, plain}).exit_code, 0);
  ASSERT_EQ(run_cli({"-q", "-o", "TILING=ALWAYS", "-tile", "65", "-co", "COMPRESS=DEFLATE", src, deflate}).exit_code, 0);
  ASSERT_EQ(run_cli({"-q", "-o", "TILING=ALWAYS", "-tile", "65", "-of", "COG", src, cog}).exit_code, 0);
  EXPECT_EQ(raw_band(deflate), raw_band(plain));
  EXPECT_EQ(raw_band(cog), raw_band(plain));
  // The work file is gone.
  EXPECT_EQ(dir.listing(), (std::vector<std::string>{"cog.tif", "deflate.tif", "plain.tif", "src.tif"}));
}

TEST(CliTiling, MaxDistanceLargerThanTheHalo) {
  TempDir dir;
  const std::string src = make_tiled_source(dir), out = dir.file("out.tif");
  ASSERT_EQ(run_cli({"-q", "-o", "TILING=ALWAYS", "-tile", "17", "-md", "40", src, out}).exit_code, 0);
  const std::vector<double> in = band_values(src), v = band_values(out);
  std::size_t voids = 0, filled = 0;
  for (std::size_t i = 0; i < v.size(); ++i)
    if (in[i] == -9999.0) {
      ++voids;
      filled += v[i] != -9999.0;
    }
  EXPECT_GT(voids, 0u);
  EXPECT_EQ(filled, voids);  // the test voids are narrower than 80 cells
}
