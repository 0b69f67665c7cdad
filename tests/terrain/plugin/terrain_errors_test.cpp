// Bad input: non-zero exit, exactly one "mcmd_terrain: error: ..." line,
// nothing left in the folder.
#include <gtest/gtest.h>

#include "terrain_support.hpp"

namespace mcmd::test {
namespace {

struct ErrorCase {
  const char* name;
  std::vector<std::string> args;  // SKETCH, DST, DIR, STATES replaced by paths
  const char* expect_in_message;
};

std::ostream& operator<<(std::ostream& os, const ErrorCase& c) { return os << c.name; }

class TerrainErrors : public ::testing::TestWithParam<ErrorCase> {};

TEST_P(TerrainErrors, OneLineNothingLeft) {
  const ErrorCase& c = GetParam();
  TempDir dir;
  Image sketch{40, 30, 1, GDT_Byte, std::vector<double>(40 * 30, 255.0)};
  sketch.values[100] = 10;
  write_image(dir.file("sketch.png"), sketch, "PNG");
  Image states{10, 10, 1, GDT_Byte, std::vector<double>(100, 0.0)};
  write_image(dir.file("states.tif"), states, "GTiff");
  Image floats{12, 12, 1, GDT_Float32, std::vector<double>(144, 5.0)};
  write_image(dir.file("float.tif"), floats, "GTiff");
  std::vector<std::string> args;
  for (const std::string& a : c.args) {
    if (a == "SKETCH") args.push_back(dir.file("sketch.png"));
    else if (a == "DST") args.push_back(dir.file("out.tif"));
    else if (a == "STATES") args.push_back(dir.file("states.tif"));
    else if (a == "FLOAT") args.push_back(dir.file("float.tif"));
    else if (a == "MISSING") args.push_back(dir.file("nothing.png"));
    else if (a == "NODIR") args.push_back(dir.file("no/such/dir/out.tif"));
    else args.push_back(a);
  }
  const auto listing = dir.listing();
  const RunResult r = run_terrain(args);
  EXPECT_NE(r.exit_code, 0);
  EXPECT_EQ(line_count(r.err), 1) << r.err;
  EXPECT_EQ(r.err.rfind("mcmd_terrain: error: ", 0), 0u) << r.err;
  EXPECT_NE(r.err.find(c.expect_in_message), std::string::npos) << r.err;
  EXPECT_EQ(dir.listing(), listing) << "a file was left behind";
}

INSTANTIATE_TEST_SUITE_P(
    BadInput, TerrainErrors,
    ::testing::Values(
        ErrorCase{"MissingSketch", {"-rs", "0.1", "MISSING", "DST"}, "no such file"},
        ErrorCase{"SketchAndSizeDisagree", {"-size", "50", "50", "SKETCH", "DST"}, "the sketch is 40x30 but -size asks 50x50"},
        ErrorCase{"ZrangeReversed", {"-zrange", "900", "100", "SKETCH", "DST"}, "MIN (900) must be below MAX (100)"},
        ErrorCase{"ZrangeEqual", {"-zrange", "5", "5", "SKETCH", "DST"}, "must be below MAX"},
        ErrorCase{"ZeroSize", {"-size", "0", "10", "-rs", "1m", "DST"}, "-size expects whole numbers of cells >= 1"},
        ErrorCase{"AbsurdSize", {"-size", "100000", "100000", "-rs", "1m", "DST"}, "too large"},
        ErrorCase{"NotANumberSize", {"-size", "big", "10", "DST"}, "-size expects"},
        ErrorCase{"NoSize", {"-rs", "1m", "DST"}, "give the terrain's size"},
        ErrorCase{"FlatFromScratch", {"-size", "20", "20", "DST"}, "the terrain would be flat"},
        ErrorCase{"FractionOfNothing", {"-size", "20", "20", "-rs", "0.5", "DST"}, "-rs 300m"},
        ErrorCase{"RsAutoOfOneCell", {"-rs", "auto", "SKETCH", "DST"}, "rs auto measures the roughness of the known terrain"},
        ErrorCase{"RsAutoOfPaper", {"-rs", "auto", "-method", "paper", "SKETCH", "DST"}, "rs auto is measured for the default method"},
        ErrorCase{"BadRs", {"-rs", "lots", "SKETCH", "DST"}, "RS=lots is invalid"},
        ErrorCase{"UnknownOption", {"-frobnicate", "SKETCH", "DST"}, "unknown option '-frobnicate'"},
        ErrorCase{"BadMethod", {"-method", "magic", "SKETCH", "DST"}, "METHOD=magic is invalid"},
        ErrorCase{"BadScheme", {"-scheme", "hexagon", "SKETCH", "DST"}, "SCHEME=hexagon is invalid"},
        ErrorCase{"BadType", {"-ot", "Complex64", "SKETCH", "DST"}, "-ot Complex64"},
        ErrorCase{"StatesWrongSize", {"-states", "STATES", "SKETCH", "DST"}, "is 10x10 but the terrain is 40x30"},
        ErrorCase{"PointOutside", {"-size", "20", "20", "-rs", "1m", "-point", "25", "3", "7", "DST"}, "outside the 20x20"},
        ErrorCase{"TwoSources", {"-skeleton", "SKETCH", "DST"}, "one source of constraints"},
        ErrorCase{"UpsampleNothing", {"-size", "33", "33", "-upsample", "4", "-rs", "1m", "DST"}, "UPSAMPLE supersamples"},
        ErrorCase{"WhiteOfFloat", {"-unknown", "white", "FLOAT", "DST"}, "this sketch is Float32"},
        ErrorCase{"EvenMedian", {"-median", "4", "SKETCH", "DST"}, "MEDIAN=4 is invalid"},
        ErrorCase{"NegativeErosion", {"-size", "33", "33", "-rs", "1m", "-erode", "-3", "DST"}, "EROSION=-3 is invalid"},
        ErrorCase{"ErosionWord", {"-size", "33", "33", "-rs", "1m", "-erode", "lots", "DST"}, "EROSION=lots is invalid"},
        ErrorCase{"ErosionLawZeroK", {"-size", "33", "33", "-rs", "1m", "-erosion", "0,0.5,1", "DST"}, "K,m,n"},
        ErrorCase{"ErosionLawBadM", {"-size", "33", "33", "-rs", "1m", "-erosion", "auto,5,1", "DST"}, "m in [0, 2]"},
        ErrorCase{"ErosionLawTwoParts", {"-size", "33", "33", "-rs", "1m", "-erosion", "1,0.5", "DST"}, "K,m,n"},
        ErrorCase{"ZeroTalus", {"-size", "33", "33", "-rs", "1m", "-talus", "0", "DST"}, "TALUS=0 is invalid"},
        ErrorCase{"NegativeDiffusion", {"-size", "33", "33", "-rs", "1m", "-diffusion", "-1", "DST"}, "DIFFUSION=-1"},
        ErrorCase{"MissingUpliftMap", {"-size", "33", "33", "-rs", "1m", "-uplift", "MISSING", "DST"}, "uplift map"},
        ErrorCase{"UpliftMapWrongSize", {"-size", "33", "33", "-rs", "1m", "-uplift", "STATES", "DST"}, "is 10x10 but the terrain is 33x33"},
        ErrorCase{"MissingDst", {}, "missing dst_file"},
        ErrorCase{"TooManyFiles", {"SKETCH", "SKETCH", "DST"}, "too many file names"},
        ErrorCase{"UnwritableDst", {"-rs", "1m", "SKETCH", "NODIR"}, "cannot write"}));

}  // namespace
}  // namespace mcmd::test
