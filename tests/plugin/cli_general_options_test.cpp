// GDAL's general options (GDALGeneralCmdLineProcessor), as every GDAL utility
// takes them, before mcmd_fillnodata's own; our --version kept.
#include <fstream>
#include <gtest/gtest.h>

#include "test_support.hpp"

namespace mcmd::test {
namespace {

bool contains(const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; }

TEST(CliGeneralOptions, ConfigSetsAnOptionForTheRun) {
  TempDir dir;
  const std::string src = dir.file("src.tif"), dst = dir.file("dst.tif");
  make_raster(src, RasterSpec{});
  // CPL_DEBUG set through --config: GDAL's debug lines show it took effect.
  const RunResult r = run_cli({"--config", "CPL_DEBUG", "ON", "--config", "GDAL_CACHEMAX", "32", "-q", src, dst});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(contains(r.err, "GDALOpen(")) << r.err;
  EXPECT_TRUE(file_exists(dst));
}

TEST(CliGeneralOptions, DebugOnPrintsGdalDebugLines) {
  TempDir dir;
  const std::string src = dir.file("src.tif"), dst = dir.file("dst.tif");
  make_raster(src, RasterSpec{});
  const RunResult r = run_cli({"--debug", "on", "-q", src, dst});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(contains(r.err, "GTiff")) << r.err;
}

TEST(CliGeneralOptions, OptfileReadsOptionsFromAFile) {
  TempDir dir;
  const std::string src = dir.file("src.tif"), a = dir.file("a.tif"), b = dir.file("b.tif");
  make_raster(src, RasterSpec{});
  std::ofstream(dir.file("opts.txt")) << "-q -md 3\n";
  ASSERT_EQ(run_cli({"--optfile", dir.file("opts.txt"), src, a}).exit_code, 0);
  ASSERT_EQ(run_cli({"-q", "-md", "3", src, b}).exit_code, 0);
  EXPECT_EQ(raw_band(a), raw_band(b));
  EXPECT_NE(raw_band(a), raw_band(src));
}

TEST(CliGeneralOptions, FormatsAndHelpGeneralPrintAndExit) {
  const RunResult formats = run_cli({"--formats"});
  EXPECT_EQ(formats.exit_code, 0);
  EXPECT_TRUE(contains(formats.out, "GTiff"));
  const RunResult general = run_cli({"--help-general"});
  EXPECT_EQ(general.exit_code, 0);
  EXPECT_TRUE(contains(general.out, "--config"));
  EXPECT_TRUE(contains(run_cli({"--help"}).out, "--help-general"));
}

TEST(CliGeneralOptions, VersionIsOurs) {
  const RunResult r = run_cli({"--version"});
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_EQ(r.out.rfind("mcmd_fillnodata ", 0), 0u) << r.out;
  EXPECT_TRUE(contains(r.out, "GDAL "));
}

TEST(CliGeneralOptions, ConfigWithoutValueIsOneErrorLine) {
  const RunResult r = run_cli({"--config", "GDAL_CACHEMAX"});
  EXPECT_NE(r.exit_code, 0);
  EXPECT_EQ(line_count(r.err), 1) << r.err;
  EXPECT_EQ(r.err.rfind("mcmd_fillnodata: error: ", 0), 0u) << r.err;
  EXPECT_TRUE(contains(r.err, "--config")) << r.err;
}

}  // namespace
}  // namespace mcmd::test
