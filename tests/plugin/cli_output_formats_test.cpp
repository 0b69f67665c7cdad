// Output drivers: one that cannot hold a band's type exactly, or that is
// lossy, is refused before the fill in one line naming the driver, the type
// and what to use instead; one the rules do not know is checked after
// writing. Every accepted driver keeps every valid cell.
#include <cmath>
#include <cstring>
#include <gtest/gtest.h>

#include "test_support.hpp"

namespace mcmd::test {
namespace {

struct FormatCase {
  const char* name;
  GDALDataType type;
  std::vector<std::string> args;  // before src and dst
  const char* dst;                // file name in the test folder
  std::vector<const char*> expect;  // in the error line (refusals only)
};

std::ostream& operator<<(std::ostream& os, const FormatCase& c) { return os << c.name; }

RasterSpec format_spec(GDALDataType type) {
  const bool unsigned_type = type == GDT_Byte || type == GDT_UInt16 || type == GDT_UInt64;
  return spec_of(type, unsigned_type ? 0.0 : -9999.0, 20, type == GDT_Byte ? 200 : 1000);
}

std::vector<std::string> with_files(std::vector<std::string> args, const std::string& src, const std::string& dst) {
  args.insert(args.begin(), "-q");
  args.push_back(src);
  args.push_back(dst);
  return args;
}

class RefusedOutput : public ::testing::TestWithParam<FormatCase> {};

TEST_P(RefusedOutput, OneLineNamingDriverAndWhatToUse) {
  const FormatCase& c = GetParam();
  TempDir dir;
  const std::string src = dir.file("src.tif");
  make_raster(src, format_spec(c.type));
  const std::string before = file_bytes(src);
  const auto listing = dir.listing();
  const RunResult r = run_cli(with_files(c.args, src, dir.file(c.dst)));
  expect_clean_failure(r, c.expect.at(0), dir, listing, src, before);
  for (const char* part : c.expect) EXPECT_NE(r.err.find(part), std::string::npos) << part << " not in: " << r.err;
}

INSTANTIATE_TEST_SUITE_P(
    TypeOrLossy, RefusedOutput,
    ::testing::Values(
        FormatCase{"PngOnInt16", GDT_Int16, {"-of", "PNG"}, "dst.png", {"PNG", "Int16", "GTiff or COG"}},
        FormatCase{"PngExtensionOnInt16", GDT_Int16, {}, "dst.png", {"PNG", "Int16", "GTiff or COG"}},
        FormatCase{"PCRasterOnFloat64", GDT_Float64, {"-of", "PCRaster"}, "dst.map", {"PCRaster", "Float64"}},
        FormatCase{"Jpeg", GDT_Byte, {"-of", "JPEG"}, "dst.jpg", {"JPEG is lossy", "Byte", "GTiff or COG"}},
        FormatCase{"Webp", GDT_Byte, {"-of", "WEBP"}, "dst.webp", {"WEBP is lossy unless -co LOSSLESS=YES"}},
        FormatCase{"Jpeg2000Default", GDT_Int16, {"-of", "JP2OpenJPEG"}, "dst.jp2", {"JPEG 2000 is lossy", "Int16"}},
        FormatCase{"CogJpeg", GDT_Byte, {"-of", "COG", "-co", "COMPRESS=JPEG"}, "dst.tif", {"COG", "COMPRESS=JPEG"}},
        FormatCase{"GTiffWebp", GDT_Byte, {"-co", "COMPRESS=WEBP"}, "dst.tif", {"GTiff", "WEBP_LOSSLESS=TRUE"}},
        FormatCase{"LercMaxZError", GDT_Float32, {"-co", "COMPRESS=LERC", "-co", "MAX_Z_ERROR=0.5"}, "dst.tif",
                   {"MAX_Z_ERROR=0.5", "Float32"}},
        FormatCase{"NbitsBelowTheType", GDT_Int16, {"-co", "NBITS=12"}, "dst.tif", {"NBITS=12", "16 bits"}},
        FormatCase{"DiscardLsb", GDT_Int16, {"-co", "DISCARD_LSB=2"}, "dst.tif", {"DISCARD_LSB"}},
        FormatCase{"CogReprojected", GDT_Int16, {"-of", "COG", "-co", "TILING_SCHEME=GoogleMapsCompatible"},
                   "dst.tif", {"TILING_SCHEME", "GTiff or COG"}},
        // Drivers whose output holds no data of its own:
        FormatCase{"VrtPointsAtOtherFiles", GDT_Int16, {"-of", "VRT"}, "dst.vrt", {"VRT", "GTiff or COG"}},
        FormatCase{"MemWritesNoFile", GDT_Int16, {"-of", "MEM"}, "dst.mem", {"MEM", "GTiff or COG"}},
        // Not in the rules, caught by the check after writing:
        FormatCase{"LossyMrfOption", GDT_Int16, {"-of", "MRF", "-co", "COMPRESS=LERC", "-co", "OPTIONS=LERC_PREC=5"},
                   "dst.mrf", {"MRF", "does not hold band 1 exactly"}},
        FormatCase{"FormatWithoutNodata", GDT_Int16, {"-of", "XYZ"}, "dst.xyz", {"XYZ", "nodata value"}}),
    [](const auto& info) { return std::string(info.param.name); });

class AcceptedOutput : public ::testing::TestWithParam<FormatCase> {};

// Valid cells keep their values (their bits when the type is kept), voids
// are filled, and the folder holds the source and the output's own files.
TEST_P(AcceptedOutput, EveryValidCellKept) {
  const FormatCase& c = GetParam();
  TempDir dir;
  const RasterSpec spec = format_spec(c.type);
  const std::string src = dir.file("src.tif"), dst = dir.file(c.dst);
  make_raster(src, spec);
  const RunResult r = run_cli(with_files(c.args, src, dst));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  for (const std::string& name : dir.listing()) EXPECT_EQ(name.find("mcmd-tmp"), std::string::npos) << name;
  const auto in = band_values(src), out = band_values(dst);
  ASSERT_EQ(in.size(), out.size());
  for (int y = 0; y < spec.height; ++y)
    for (int x = 0; x < spec.width; ++x) {
      const std::size_t i = static_cast<std::size_t>(y) * spec.width + x;
      if (is_test_void(x, y, spec.width, spec.height)) {
        ASSERT_TRUE(std::isfinite(out[i]) && out[i] != *spec.nodata) << "void left at " << x << "," << y;
      } else {
        ASSERT_EQ(out[i], in[i]) << "valid cell changed at " << x << "," << y;
      }
    }
  GDALDataset* ds = GDALDataset::Open(dst.c_str(), GDAL_OF_RASTER);
  ASSERT_NE(ds, nullptr);
  const GDALDataType written = ds->GetRasterBand(1)->GetRasterDataType();
  GDALClose(ds);
  if (written != c.type) return;  // a format without types (AAIGrid): the values are what is kept
  const auto raw_in = raw_band(src), raw_out = raw_band(dst);
  const std::size_t bytes = GDALGetDataTypeSizeBytes(c.type);
  for (std::size_t i = 0; i < in.size(); ++i) {
    if (is_test_void(static_cast<int>(i % spec.width), static_cast<int>(i / spec.width), spec.width, spec.height))
      continue;
    ASSERT_EQ(std::memcmp(&raw_in[i * bytes], &raw_out[i * bytes], bytes), 0) << "bits changed at cell " << i;
  }
}

INSTANTIATE_TEST_SUITE_P(
    Lossless, AcceptedOutput,
    ::testing::Values(FormatCase{"PngByte", GDT_Byte, {"-of", "PNG"}, "dst.png", {}},
                      FormatCase{"PngUInt16", GDT_UInt16, {}, "dst.png", {}},
                      FormatCase{"Jpeg2000Reversible", GDT_Int16,
                                 {"-of", "JP2OpenJPEG", "-co", "QUALITY=100", "-co", "REVERSIBLE=YES"}, "dst.jp2", {}},
                      FormatCase{"CogInt64", GDT_Int64, {"-of", "COG", "-co", "COMPRESS=DEFLATE"}, "dst.tif", {}},
                      FormatCase{"CogFloat64", GDT_Float64, {"-of", "COG", "-co", "COMPRESS=ZSTD"}, "dst.tif", {}},
                      FormatCase{"LercLossless", GDT_Float32, {"-co", "COMPRESS=LERC", "-co", "MAX_Z_ERROR=0"},
                                 "dst.tif", {}},
                      FormatCase{"AsciiGridWidensInt16", GDT_Int16, {"-of", "AAIGrid"}, "dst.asc", {}},
                      FormatCase{"Erdas", GDT_Float32, {"-of", "HFA"}, "dst.img", {}},
                      FormatCase{"NetCdf", GDT_Float64, {"-of", "netCDF"}, "dst.nc", {}},
                      FormatCase{"EnviWithHeader", GDT_Int32, {"-of", "ENVI"}, "dst.envi", {}},
                      FormatCase{"MrfOfThreeFiles", GDT_Int16, {"-of", "MRF"}, "dst.mrf", {}}),
    [](const auto& info) { return std::string(info.param.name); });

}  // namespace
}  // namespace mcmd::test
