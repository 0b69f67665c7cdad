// Bad input: non-zero exit, exactly one "mcmd_fillnodata: error: ..." line on
// stderr, no output or temporary file left, the source untouched.
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <gtest/gtest.h>
#include <unistd.h>

#include "test_support.hpp"

namespace mcmd::test {
namespace {

struct ErrorCase {
  const char* name;
  // Arguments; "SRC", "DST", "MASK", "DIR" are replaced by paths in the test folder.
  std::vector<std::string> args;
  const char* expect_in_message;
  const char* shell_prefix = "";
  const char* src_kind = "peaks";  // peaks | all_nodata | no_nodata | text | missing | big | alpha | png
};

std::ostream& operator<<(std::ostream& os, const ErrorCase& c) { return os << c.name; }

void make_source(const std::string& kind, const std::string& path) {
  RasterSpec spec;
  if (kind == "missing") return;
  if (kind == "text") {
    std::ofstream(path) << "this is not a raster\n";
    return;
  }
  if (kind == "all_nodata") {
    spec.base = -32768;
    spec.scale = 0;
  }
  if (kind == "no_nodata") spec.nodata = std::nullopt;
  if (kind == "big") {
    spec.type = GDT_Float32;
    spec.width = spec.height = 300;
    spec.nodata = -9999.0;
  }
  if (kind == "alpha") spec.bands = 2;
  if (kind == "png") {
    spec.type = GDT_Byte;
    spec.nodata = 0.0;
    spec.base = 20;
  }
  make_raster(kind == "png" ? path + ".tif" : path, spec);
  if (kind == "alpha") {
    GDALDataset* ds = GDALDataset::Open(path.c_str(), GDAL_OF_RASTER | GDAL_OF_UPDATE);
    ds->GetRasterBand(2)->SetColorInterpretation(GCI_AlphaBand);
    GDALClose(ds);
  }
  if (kind == "png") {  // a format GDAL reads but cannot update
    GDALDataset* tif = GDALDataset::Open((path + ".tif").c_str(), GDAL_OF_RASTER);
    GDALDriver* png = GetGDALDriverManager()->GetDriverByName("PNG");
    GDALClose(png->CreateCopy(path.c_str(), tif, FALSE, nullptr, nullptr, nullptr));
    GDALClose(tif);
    std::remove((path + ".tif").c_str());
    std::remove((path + ".aux.xml").c_str());
  }
}

class CliErrors : public ::testing::TestWithParam<ErrorCase> {};

TEST_P(CliErrors, OneLineNoOutputSourceUntouched) {
  const ErrorCase& c = GetParam();
  TempDir dir;
  const std::string src = dir.file("src.tif"), dst = dir.file("dst.tif");
  make_source(c.src_kind, src);
  make_mask(dir.file("mask.tif"), 10, 10);  // wrong size on purpose
  std::vector<std::string> args;
  for (const std::string& a : c.args) {
    if (a == "SRC") args.push_back(src);
    else if (a == "DST") args.push_back(dst);
    else if (a == "MASK") args.push_back(dir.file("mask.tif"));
    else if (a == "NODIR") args.push_back(dir.file("no/such/dir/out.tif"));
    else if (a == "ADIR") {
      std::filesystem::create_directory(dir.file("adir"));
      args.push_back(dir.file("adir"));
    }
    else args.push_back(a);
  }
  const std::string before = file_exists(src) ? file_bytes(src) : "";
  const auto listing = dir.listing();

  const RunResult r = run_cli(args, c.shell_prefix);

  expect_clean_failure(r, c.expect_in_message, dir, listing, src, before);
  EXPECT_FALSE(file_exists(dst));
}

INSTANTIATE_TEST_SUITE_P(
    BadInput, CliErrors,
    ::testing::Values(
        ErrorCase{"MissingFile", {"SRC", "DST"}, "no such file", "", "missing"},
        ErrorCase{"UnreadableFile", {"SRC", "DST"}, "cannot open", "", "text"},
        ErrorCase{"BandOutOfRange", {"-b", "2", "SRC", "DST"}, "band 2 is out of range"},
        ErrorCase{"BandZero", {"-b", "0", "SRC", "DST"}, "-b expects"},
        ErrorCase{"UnknownFlag", {"-frobnicate", "SRC", "DST"}, "unknown option '-frobnicate'"},
        ErrorCase{"MissingValue", {"SRC", "DST", "-H"}, "-H expects a value"},
        ErrorCase{"HOutOfRange", {"-H", "1.5", "SRC", "DST"}, "H=1.5"},
        ErrorCase{"NegativeRs", {"-rs", "-0.1", "SRC", "DST"}, "RS=-0.1"},
        ErrorCase{"MaxVoidNotWhole", {"-maxvoid", "1.5", "SRC", "DST"}, "MAX_VOID=1.5"},
        ErrorCase{"MaxVoidUnknownUnit", {"-maxvoid", "3acres", "SRC", "DST"}, "MAX_VOID=3acres"},
        ErrorCase{"MaxVoidBelowOneCell", {"-maxvoid", "100m2", "SRC", "DST"}, "smaller than one cell"},
        ErrorCase{"NonNumeric", {"-I", "steep", "SRC", "DST"}, "I=steep"},
        ErrorCase{"TileNotPowerOfTwoPlusOne", {"-tile", "100", "SRC", "DST"}, "TILE_SIZE=100"},
        ErrorCase{"UnknownTiling", {"-o", "TILING=SOMETIMES", "SRC", "DST"}, "TILING=SOMETIMES"},
        ErrorCase{"ZeroThreads", {"-threads", "0", "SRC", "DST"}, "NUM_THREADS=0"},
        ErrorCase{"UnknownMethod", {"-method", "kriging", "SRC", "DST"}, "METHOD=kriging"},
        ErrorCase{"NegativeMaxDistance", {"-md", "-5", "SRC", "DST"}, "MAX_DISTANCE=-5"},
        ErrorCase{"HexadecimalNumber", {"-md", "0x10", "SRC", "DST"}, "MAX_DISTANCE=0x10"},
        ErrorCase{"InfiniteNumber", {"-I", "inf", "SRC", "DST"}, "I=inf"},
        ErrorCase{"NaNNumber", {"-rt", "nan", "SRC", "DST"}, "RT=nan"},
        ErrorCase{"HexadecimalInOption", {"-o", "RIDGE_I=0x1p1", "SRC", "DST"}, "RIDGE_I=0x1p1"},
        ErrorCase{"BlankBeforeNumber", {"-H", " 0.5", "SRC", "DST"}, "H= 0.5"},
        ErrorCase{"SignedBandNumber", {"-b", "+1", "SRC", "DST"}, "-b expects"},
        ErrorCase{"AlphaBand", {"-b", "2", "SRC", "DST"}, "band 2 is an alpha band", "", "alpha"},
        ErrorCase{"DestinationIsAFolder", {"SRC", "ADIR"}, "it is a folder"},
        ErrorCase{"InPlaceFormatNotUpdatable", {"SRC"}, "PNG driver cannot change it in place", "", "png"},
        ErrorCase{"UnknownAlgorithmOption", {"-o", "FOO=1", "SRC", "DST"}, "unknown option 'FOO'"},
        ErrorCase{"TooManyFiles", {"SRC", "DST", "DST"}, "too many file names"},
        ErrorCase{"NoFile", {"-q"}, "missing src_file"},
        ErrorCase{"AllNodata", {"SRC", "DST"}, "no valid cell", "", "all_nodata"},
        ErrorCase{"AllNodataInPlace", {"SRC"}, "no valid cell", "", "all_nodata"},
        ErrorCase{"NoNodataDefined", {"SRC", "DST"}, "nothing marks the voids", "", "no_nodata"},
        ErrorCase{"NoNodataInPlace", {"SRC"}, "nothing marks the voids", "", "no_nodata"},
        ErrorCase{"BadDriver", {"-of", "NoSuchFormat", "SRC", "DST"}, "unknown output format"},
        ErrorCase{"ReadOnlyDriver", {"-of", "JDEM", "SRC", "DST"}, "cannot write rasters"},
        ErrorCase{"BadCreationOption", {"-co", "COMPRESS=WHIZZ", "SRC", "DST"}, "invalid creation option"},
        ErrorCase{"MaskSizeMismatch", {"-mask", "MASK", "SRC", "DST"}, "mask"},
        ErrorCase{"MissingMask", {"-mask", "DST", "SRC"}, "no such file"},
        ErrorCase{"OutputFolderMissing", {"SRC", "NODIR"}, "cannot write"},
        ErrorCase{"DiskFull", {"-q", "SRC", "DST"}, "cannot write", "ulimit -f 64;", "big"}),
    [](const auto& info) { return std::string(info.param.name); });

// In place on a file the user may not write: a permission problem, said so
// (GDAL's open for update called it "not a raster format GDAL can read").
// Root may write any file: as root the run is made as nobody.
TEST(CliErrorsInPlace, ReadOnlyFileIsAPermissionProblem) {
  TempDir dir;
  const std::string src = dir.file("src.tif");
  make_raster(src, RasterSpec{});
  std::filesystem::permissions(dir.path(), std::filesystem::perms(0755));
  std::filesystem::permissions(src, std::filesystem::perms(0444));
  const std::string before = file_bytes(src);
  const auto listing = dir.listing();
  const RunResult r = ::geteuid() == 0 ? run_cli_under({"/usr/bin/setpriv", "--reuid=65534", "--regid=65534",
                                                        "--clear-groups"},
                                                       {"-q", src})
                                       : run_cli({"-q", src});
  expect_clean_failure(r, "Permission denied", dir, listing, src, before);
  EXPECT_NE(r.err.find("give a dst_file"), std::string::npos) << r.err;
}

// A compressed source with one corrupt block, copied for a tiled fill: the
// copy decodes blocks on GDAL's threads (GDAL_NUM_THREADS), whose errors
// have no handler of the CLI's thread. Still one line, naming no internal
// in-memory file, and nothing left behind.
TEST(CliErrorsCorrupt, BlockDecodedOnGdalThreadsIsOneLine) {
  TempDir dir;
  const std::string src = dir.file("src.tif"), dst = dir.file("dst.tif");
  RasterSpec spec;
  spec.creation_options = {"COMPRESS=LZW", "TILED=YES", "BLOCKXSIZE=16", "BLOCKYSIZE=16"};
  make_raster(src, spec);
  GDALDataset* ds = GDALDataset::Open(src.c_str(), GDAL_OF_RASTER);
  ASSERT_NE(ds, nullptr);
  const char* offset = ds->GetRasterBand(1)->GetMetadataItem("BLOCK_OFFSET_1_1", "TIFF");
  const char* size = ds->GetRasterBand(1)->GetMetadataItem("BLOCK_SIZE_1_1", "TIFF");
  ASSERT_TRUE(offset && size);
  const long at = std::stol(offset), bytes = std::stol(size);
  GDALClose(ds);
  {
    std::fstream f(src, std::ios::in | std::ios::out | std::ios::binary);
    f.seekp(at);
    for (long k = 0; k < bytes; ++k) f.put(static_cast<char>(0xFF));
  }
  const std::string before = file_bytes(src);
  const auto listing = dir.listing();
  for (const char* threads : {"1", "2"}) {
    const RunResult r = run_cli({"-q", "-o", "TILING=ALWAYS", "-threads", threads, src, dst});
    expect_clean_failure(r, "cannot write", dir, listing, src, before);
    EXPECT_EQ(r.err.find("/vsimem/"), std::string::npos) << r.err;
    EXPECT_FALSE(file_exists(dst));
  }
}

}  // namespace
}  // namespace mcmd::test
