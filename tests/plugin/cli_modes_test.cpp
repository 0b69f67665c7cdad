// mcmd_fillnodata end to end: metadata kept, mask file, in place, multi-band,
// output formats and creation options, -md, determinism, progress and help.
#include <cmath>
#include <cstring>
#include <gtest/gtest.h>

#include "test_support.hpp"

namespace mcmd::test {
namespace {

std::size_t count_equal(const std::vector<double>& v, double x) {
  std::size_t n = 0;
  for (double e : v) n += e == x ? 1 : 0;
  return n;
}

TEST(CliModes, KeepsCrsGeotransformNodataMetadataAndDescriptions) {
  TempDir dir;
  const std::string src = dir.file("src.tif"), dst = dir.file("dst.tif");
  make_raster(src, RasterSpec{});
  ASSERT_EQ(run_cli({"-q", src, dst}).exit_code, 0);
  GDALDataset* in = GDALDataset::Open(src.c_str(), GDAL_OF_RASTER);
  GDALDataset* out = GDALDataset::Open(dst.c_str(), GDAL_OF_RASTER);
  ASSERT_TRUE(in && out);
  ASSERT_NE(out->GetSpatialRef(), nullptr);
  EXPECT_TRUE(out->GetSpatialRef()->IsSame(in->GetSpatialRef()));
  EXPECT_EQ(out->GetSpatialRef()->GetAuthorityCode(nullptr), std::string("32611"));
  double gi[6], go[6];
  ASSERT_EQ(out->GetGeoTransform(go), CE_None);
  in->GetGeoTransform(gi);
  for (int i = 0; i < 6; ++i) EXPECT_EQ(gi[i], go[i]);
  EXPECT_STREQ(out->GetMetadataItem("MCMD_TEST"), "dataset item");
  GDALRasterBand* b = out->GetRasterBand(1);
  int has = 0;
  EXPECT_EQ(b->GetNoDataValue(&has), -32768.0);
  EXPECT_TRUE(has);
  EXPECT_STREQ(b->GetDescription(), "elevation 1");
  EXPECT_STREQ(b->GetMetadataItem("BAND_NOTE"), "band 1");
  EXPECT_STREQ(b->GetUnitType(), "m");
  EXPECT_EQ(b->GetColorInterpretation(), in->GetRasterBand(1)->GetColorInterpretation());
  GDALClose(in);
  GDALClose(out);
}

TEST(CliModes, MaskFileMarksTheVoids) {
  TempDir dir;
  RasterSpec spec;
  spec.nodata = std::nullopt;  // voids hold -32768 but nothing says so...
  const std::string src = dir.file("src.tif"), dst = dir.file("dst.tif"), mask = dir.file("mask.tif");
  make_raster(src, spec);
  make_mask(mask, spec.width, spec.height);  // ...except the mask
  const RunResult r = run_cli({"-q", "-mask", mask, src, dst});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto in = band_values(src), out = band_values(dst);
  for (int y = 0; y < spec.height; ++y)
    for (int x = 0; x < spec.width; ++x) {
      const std::size_t i = static_cast<std::size_t>(y) * spec.width + x;
      if (is_test_void(x, y, spec.width, spec.height)) {
        ASSERT_GT(out[i], 0.0) << "void not filled at " << x << "," << y;
      } else {
        ASSERT_EQ(out[i], in[i]);
      }
    }
}

// -nomask: the band's nodata value marks nothing (its cells are values like
// any other); only the -mask file's voids are filled. The plugin reads an
// integer band's nodata cells itself, so this must hold there too.
TEST(CliModes, NoMaskIgnoresTheNodataValue) {
  TempDir dir;
  RasterSpec spec;  // Int16, nodata -32768 on the test voids
  const std::string src = dir.file("src.tif"), dst = dir.file("dst.tif"), mask = dir.file("mask.tif");
  make_raster(src, spec);
  const auto in = band_values(src);
  // The mask's only void: a 5×5 block of valid cells.
  const auto in_block = [](int x, int y) { return x >= 30 && x < 35 && y >= 5 && y < 10; };
  {
    GDALDriver* gtiff = GetGDALDriverManager()->GetDriverByName("GTiff");
    GDALDataset* m = gtiff->Create(mask.c_str(), spec.width, spec.height, 1, GDT_Byte, nullptr);
    ASSERT_NE(m, nullptr);
    std::vector<GByte> v(static_cast<std::size_t>(spec.width) * spec.height, 255);
    for (int y = 0; y < spec.height; ++y)
      for (int x = 0; x < spec.width; ++x) {
        ASSERT_FALSE(in_block(x, y) && is_test_void(x, y, spec.width, spec.height));
        if (in_block(x, y)) v[static_cast<std::size_t>(y) * spec.width + x] = 0;
      }
    ASSERT_EQ(m->GetRasterBand(1)->RasterIO(GF_Write, 0, 0, spec.width, spec.height, v.data(), spec.width,
                                            spec.height, GDT_Byte, 0, 0, nullptr),
              CE_None);
    GDALClose(m);
  }
  const RunResult r = run_cli({"-q", "-nomask", "-mask", mask, src, dst});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto out = band_values(dst);
  int filled = 0;
  for (int y = 0; y < spec.height; ++y)
    for (int x = 0; x < spec.width; ++x) {
      const std::size_t i = static_cast<std::size_t>(y) * spec.width + x;
      if (in_block(x, y)) {
        filled += out[i] != in[i];
      } else {
        ASSERT_EQ(out[i], in[i]) << "cell outside the mask's void changed at " << x << "," << y;
      }
    }
  EXPECT_GT(filled, 0);
}

// The source's own per-dataset mask (no nodata value) marks the voids, also
// when the fill reads its values back from the uncompressed output copy, and
// in a compressed output (through the work copy).
TEST(CliModes, SourceMaskBandMarksTheVoids) {
  TempDir dir;
  RasterSpec spec;
  spec.nodata = std::nullopt;
  const std::string src = dir.file("src.tif");
  make_raster(src, spec);
  {
    GDALDataset* ds = GDALDataset::Open(src.c_str(), GDAL_OF_RASTER | GDAL_OF_UPDATE);
    ASSERT_NE(ds, nullptr);
    ASSERT_EQ(ds->CreateMaskBand(GMF_PER_DATASET), CE_None);
    std::vector<GByte> m(static_cast<std::size_t>(spec.width) * spec.height, 255);
    for (int y = 0; y < spec.height; ++y)
      for (int x = 0; x < spec.width; ++x)
        if (is_test_void(x, y, spec.width, spec.height)) m[static_cast<std::size_t>(y) * spec.width + x] = 0;
    ASSERT_EQ(ds->GetRasterBand(1)->GetMaskBand()->RasterIO(GF_Write, 0, 0, spec.width, spec.height, m.data(),
                                                             spec.width, spec.height, GDT_Byte, 0, 0, nullptr),
              CE_None);
    GDALClose(ds);
  }
  const auto in = band_values(src);
  for (const std::vector<std::string>& extra : {std::vector<std::string>{}, {"-co", "COMPRESS=DEFLATE"}}) {
    const std::string dst = dir.file(extra.empty() ? "plain.tif" : "deflate.tif");
    std::vector<std::string> args{"-q"};
    args.insert(args.end(), extra.begin(), extra.end());
    args.push_back(src);
    args.push_back(dst);
    const RunResult r = run_cli(args);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const auto out = band_values(dst);
    for (int y = 0; y < spec.height; ++y)
      for (int x = 0; x < spec.width; ++x) {
        const std::size_t i = static_cast<std::size_t>(y) * spec.width + x;
        if (is_test_void(x, y, spec.width, spec.height))
          ASSERT_GT(out[i], 0.0) << dst << ": void not filled at " << x << "," << y;
        else
          ASSERT_EQ(out[i], in[i]);
      }
  }
}

TEST(CliModes, InPlaceFillsTheSource) {
  TempDir dir;
  const std::string src = dir.file("src.tif");
  make_raster(src, RasterSpec{});
  const auto before = raw_band(src);
  const RunResult r = run_cli({"-q", src});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(count_equal(band_values(src), -32768.0), 0u);
  const auto after = raw_band(src);
  const RasterSpec spec;
  for (int y = 0; y < spec.height; ++y)
    for (int x = 0; x < spec.width; ++x)
      if (!is_test_void(x, y, spec.width, spec.height)) {
        const std::size_t i = 2 * (static_cast<std::size_t>(y) * spec.width + x);
        ASSERT_EQ(std::memcmp(&before[i], &after[i], 2), 0);
      }
  EXPECT_EQ(dir.listing(), std::vector<std::string>{"src.tif"});
}

TEST(CliModes, OnlySelectedBandIsFilled) {
  TempDir dir;
  RasterSpec spec;
  spec.bands = 2;
  const std::string src = dir.file("src.tif"), dst = dir.file("dst.tif");
  make_raster(src, spec);
  ASSERT_EQ(run_cli({"-q", "-b", "2", src, dst}).exit_code, 0);
  EXPECT_EQ(raw_band(dst, 1), raw_band(src, 1)) << "band 1 must be copied unchanged";
  EXPECT_GT(count_equal(band_values(src, 2), -32768.0), 0u);
  EXPECT_EQ(count_equal(band_values(dst, 2), -32768.0), 0u);
}

TEST(CliModes, EveryBandByDefault) {
  TempDir dir;
  RasterSpec spec;
  spec.bands = 2;
  const std::string src = dir.file("src.tif"), dst = dir.file("dst.tif");
  make_raster(src, spec);
  ASSERT_EQ(run_cli({"-q", src, dst}).exit_code, 0);
  EXPECT_EQ(count_equal(band_values(dst, 1), -32768.0), 0u);
  EXPECT_EQ(count_equal(band_values(dst, 2), -32768.0), 0u);
}

TEST(CliModes, CreationOptionsReachTheDriver) {
  TempDir dir;
  const std::string src = dir.file("src.tif"), dst = dir.file("dst.tif");
  make_raster(src, RasterSpec{});
  ASSERT_EQ(run_cli({"-q", "-of", "GTiff", "-co", "COMPRESS=DEFLATE", "-co", "TILED=YES", src, dst}).exit_code, 0);
  GDALDataset* out = GDALDataset::Open(dst.c_str(), GDAL_OF_RASTER);
  ASSERT_NE(out, nullptr);
  EXPECT_STREQ(out->GetMetadataItem("COMPRESSION", "IMAGE_STRUCTURE"), "DEFLATE");
  int bx = 0, by = 0;
  out->GetRasterBand(1)->GetBlockSize(&bx, &by);
  EXPECT_EQ(bx, 256);
  GDALClose(out);
}

TEST(CliModes, CogOutput) {
  TempDir dir;
  const std::string src = dir.file("src.tif"), dst = dir.file("dst.tif");
  make_raster(src, RasterSpec{});
  const RunResult r = run_cli({"-q", "-of", "COG", "-co", "COMPRESS=DEFLATE", src, dst});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  GDALDataset* out = GDALDataset::Open(dst.c_str(), GDAL_OF_RASTER);
  ASSERT_NE(out, nullptr);
  EXPECT_STREQ(out->GetMetadataItem("LAYOUT", "IMAGE_STRUCTURE"), "COG");
  GDALClose(out);
  EXPECT_EQ(count_equal(band_values(dst), -32768.0), 0u);
  EXPECT_EQ(dir.listing(), (std::vector<std::string>{"dst.tif", "src.tif"}));
}

TEST(CliModes, MaxDistanceLeavesFarCellsVoid) {
  TempDir dir;
  const std::string src = dir.file("src.tif"), near = dir.file("near.tif"), all = dir.file("all.tif");
  make_raster(src, RasterSpec{});
  ASSERT_EQ(run_cli({"-q", "-md", "1", src, near}).exit_code, 0);
  ASSERT_EQ(run_cli({"-q", "-md", "0", src, all}).exit_code, 0);
  const std::size_t voids = count_equal(band_values(src), -32768.0);
  const std::size_t left = count_equal(band_values(near), -32768.0);
  EXPECT_GT(left, 0u);
  EXPECT_LT(left, voids);  // single cells and the stripe edges are within 1 cell
  EXPECT_EQ(count_equal(band_values(all), -32768.0), 0u);
}

TEST(CliModes, RasterWithoutVoidsIsCopiedUnchanged) {
  TempDir dir;
  RasterSpec spec;
  spec.voids = false;  // nodata declared, but no cell holds it
  const std::string src = dir.file("src.tif"), dst = dir.file("dst.tif");
  make_raster(src, spec);
  const RunResult r = run_cli({"-q", src, dst});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(raw_band(dst), raw_band(src));
}

TEST(CliModes, SameRunTwiceGivesIdenticalPixels) {
  TempDir dir;
  const std::string src = dir.file("src.tif"), a = dir.file("a.tif"), b = dir.file("b.tif");
  RasterSpec spec;
  spec.type = GDT_Float32;
  spec.nodata = -9999.0;
  make_raster(src, spec);
  for (const char* method : {"mcmd", "paper-ds", "paper-te"}) {
    ASSERT_EQ(run_cli({"-q", "-method", method, "-rs", "0.05", "-seed", "7", src, a}).exit_code, 0);
    ASSERT_EQ(run_cli({"-q", "-method", method, "-rs", "0.05", "-seed", "7", src, b}).exit_code, 0);
    EXPECT_EQ(raw_band(a), raw_band(b)) << method;
  }
}

TEST(CliModes, ProgressReachesDoneAndQuietPrintsNothing) {
  TempDir dir;
  const std::string src = dir.file("src.tif");
  make_raster(src, RasterSpec{});
  const RunResult loud = run_cli({src, dir.file("a.tif")});
  ASSERT_EQ(loud.exit_code, 0) << loud.err;
  EXPECT_EQ(loud.out, "0...10...20...30...40...50...60...70...80...90...100 - done.\n");
  EXPECT_EQ(loud.err, "");
  const RunResult quiet = run_cli({"-q", src, dir.file("b.tif")});
  EXPECT_EQ(quiet.out, "");
  EXPECT_EQ(quiet.err, "");
}

TEST(CliModes, HelpExplainsEveryFlagAndVersionNamesGdal) {
  const RunResult help = run_cli({"--help"});
  EXPECT_EQ(help.exit_code, 0);
  for (const char* flag : {"-q", "-b", "-mask", "-nomask", "-md", "-of", "-co", "-method", "-I ", "-Ibu", "-H ",
                           "-rt", "-rs", "-seed", "-tile", "-threads", "--version", "FRACTION OF THE KNOWN ELEVATION"})
    EXPECT_NE(help.out.find(flag), std::string::npos) << flag;
  const RunResult version = run_cli({"--version"});
  EXPECT_EQ(version.exit_code, 0);
  EXPECT_NE(version.out.find("GDAL"), std::string::npos);
}

TEST(CliModes, TestdataFilesWhenPresent) {
  const std::string dir = MCMD_TESTDATA_DIR;
  if (!file_exists(dir + "/peaks_mask.tif") || !file_exists(dir + "/peaks_2band.tif")) GTEST_SKIP();
  TempDir tmp;
  for (const char* f : {"peaks_int16_geo.tif", "peaks_float32_utm.tif", "peaks_float32_nan.tif", "peaks_2band.tif"}) {
    const RunResult r = run_cli({"-q", dir + "/" + f, tmp.file(f)});
    EXPECT_EQ(r.exit_code, 0) << f << ": " << r.err;
  }
  const RunResult r = run_cli({"-q", "-mask", dir + "/peaks_mask.tif", dir + "/peaks_nonodata.tif", tmp.file("m.tif")});
  EXPECT_EQ(r.exit_code, 0) << r.err;
  for (const char* f : {"all_nodata.tif", "no_nodata.tif"})
    EXPECT_NE(run_cli({"-q", dir + "/" + f, tmp.file(f)}).exit_code, 0) << f;
}

}  // namespace
}  // namespace mcmd::test
