#include "terrain/terrain_args.hpp"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <map>

#include "cli/args.hpp"
#include "cpl_string.h"
#include "gdal.h"

namespace mcmd::cli {

namespace {

// Flags that are shorthands for one MCMDTerrain option with one value.
const std::map<std::string, std::string>& option_flags() {
  static const std::map<std::string, std::string> table = {
      {"-method", "METHOD"},     {"-scheme", "SCHEME"},       {"-sharpness", "SHARPNESS"},
      {"-rs", "RS"},             {"-H", "H"},                 {"-rt", "RT"},
      {"-seed", "SEED"},         {"-I", "I"},                 {"-Ibu", "I_BU"},
      {"-ridge-I", "RIDGE_I"},   {"-ridge-Ibu", "RIDGE_I_BU"}, {"-river-I", "RIVER_I"},
      {"-river-Ibu", "RIVER_I_BU"}, {"-delta", "DELTA"},      {"-threads", "NUM_THREADS"},
      {"-unknown", "UNKNOWN"},   {"-ridge-couples", "RIDGE_COUPLES"}, {"-river-particles", "RIVER_PARTICLES"},
      {"-peaks", "PEAKS"},       {"-peaks-noise", "PEAKS_NOISE"}, {"-peaks-threshold", "PEAKS_THRESHOLD"},
      {"-states", "STATES"},     {"-ridges", "RIDGES"},       {"-rivers", "RIVERS"},
      {"-ridge-z", "RIDGE_Z"},   {"-river-z", "RIVER_Z"},     {"-upsample", "UPSAMPLE"},   {"-median", "MEDIAN"},
      {"-median-passes", "MEDIAN_PASSES"}, {"-erode", "EROSION"}, {"-erosion", "EROSION_LAW"},
      {"-uplift", "UPLIFT"},     {"-diffusion", "DIFFUSION"}, {"-talus", "TALUS"},
  };
  return table;
}

// Flags without a value that set an option to YES.
const std::map<std::string, std::string>& switch_flags() {
  static const std::map<std::string, std::string> table = {{"-skeleton", "SKELETON"}, {"-median-all", "MEDIAN_ALL"}};
  return table;
}

class Reader {
 public:
  Reader(int argc, const char* const* argv) : argc_(argc), argv_(argv) {}
  bool done() const { return i_ >= argc_; }
  std::string next() { return argv_[i_++]; }
  std::string value_of(const std::string& flag, const char* what = "a value") {
    if (done()) throw UsageError(flag + " expects " + what);
    return next();
  }
  double number_of(const std::string& flag, const char* what) {
    const std::string s = value_of(flag, what);
    char* end = nullptr;
    errno = 0;
    const double v = std::strtod(s.c_str(), &end);
    if (s.empty() || *end != '\0' || errno == ERANGE || !std::isfinite(v))
      throw UsageError(flag + " expects " + what + ", got '" + s + "'");
    return v;
  }

 private:
  int argc_;
  const char* const* argv_;
  int i_ = 1;
};

int size_of(Reader& in, const std::string& flag) {
  const double v = in.number_of(flag, "a width and a height (whole numbers of cells)");
  if (v != std::floor(v) || v < 1 || v > 1e9)
    throw UsageError(flag + " expects whole numbers of cells >= 1, got '" + CPLSPrintf("%.17g", v) + "'");
  return static_cast<int>(v);
}

void add_point(TerrainArgs& a, Reader& in) {
  const char* what = "a column, a row and an elevation";
  const double c = in.number_of("-point", what), r = in.number_of("-point", what), z = in.number_of("-point", what);
  a.options.push_back(CPLSPrintf("POINTS=%.17g,%.17g,%.17g", c, r, z));
}

bool handle_flag(TerrainArgs& a, const std::string& flag, Reader& in) {
  if (flag == "--help" || flag == "-h" || flag == "-help") a.help = true;
  else if (flag == "--version") a.version = true;
  else if (flag == "-q" || flag == "-quiet") a.quiet = true;
  else if (flag == "-size") a.width = size_of(in, flag), a.height = size_of(in, flag);
  else if (flag == "-ot") a.type = in.value_of(flag, "a data type");
  else if (flag == "-of") a.format = in.value_of(flag, "a format");
  else if (flag == "-co") a.creation_options.push_back(in.value_of(flag, "NAME=VALUE"));
  else if (flag == "-a_srs") a.srs = in.value_of(flag, "a CRS");
  else if (flag == "-a_nodata") a.nodata = in.number_of(flag, "a number");
  else if (flag == "-like") a.like = in.value_of(flag, "a raster file");
  else if (flag == "-hillshade") a.hillshade = in.value_of(flag, "a PNG file name");
  else if (flag == "-o") a.options.push_back(in.value_of(flag, "NAME=VALUE"));
  else if (flag == "-point") add_point(a, in);
  else if (flag == "-b") {
    const double b = in.number_of(flag, "a band number");
    if (b != std::floor(b) || b < 1 || b > 1e6) throw UsageError("-b expects a band number >= 1");
    a.band = static_cast<int>(b);
  } else if (flag == "-a_ullr") {
    const char* what = "ulx uly lrx lry";
    GeoBox g;
    g.ulx = in.number_of(flag, what), g.uly = in.number_of(flag, what);
    g.lrx = in.number_of(flag, what), g.lry = in.number_of(flag, what);
    if (g.ulx == g.lrx || g.uly == g.lry) throw UsageError("-a_ullr: the box ulx uly lrx lry is empty");
    a.ullr = g;
  } else if (flag == "-zrange") {
    const double lo = in.number_of(flag, "MIN MAX"), hi = in.number_of(flag, "MIN MAX");
    if (lo >= hi) throw UsageError(CPLSPrintf("-zrange MIN MAX: MIN (%g) must be below MAX (%g)", lo, hi));
    a.options.push_back(CPLSPrintf("ZRANGE=%.17g,%.17g", lo, hi));
  } else if (auto it = switch_flags().find(flag); it != switch_flags().end()) {
    a.options.push_back(it->second + "=YES");
  } else if (auto it2 = option_flags().find(flag); it2 != option_flags().end()) {
    a.options.push_back(it2->second + "=" + in.value_of(flag));
  } else {
    return false;
  }
  return true;
}

// Several -point flags are one POINTS option.
CPLStringList merged(const std::vector<std::string>& options) {
  CPLStringList out;
  std::string points;
  for (const std::string& o : options) {
    if (o.rfind("POINTS=", 0) != 0) {
      out.AddString(o.c_str());
      continue;
    }
    if (!points.empty()) points.push_back(';');
    points.append(o, 7);
  }
  if (!points.empty()) out.AddString(("POINTS=" + points).c_str());
  return out;
}

}  // namespace

TerrainArgs parse_terrain_args(int argc, const char* const* argv) {
  TerrainArgs a;
  Reader in(argc, argv);
  std::vector<std::string> files;
  while (!in.done()) {
    const std::string s = in.next();
    if (s.size() > 1 && s[0] == '-' && !(s[1] >= '0' && s[1] <= '9')) {
      if (!handle_flag(a, s, in)) throw UsageError("unknown option '" + s + "' (see --help)");
    } else {
      files.push_back(s);
    }
  }
  if (a.help || a.version) return a;
  if (files.empty()) throw UsageError("missing dst_file (usage: mcmd_terrain [options] [sketch_file] dst_file)");
  if (files.size() > 2) throw UsageError("too many file names: '" + files[2] + "' (expected [sketch_file] dst_file)");
  a.dst = files.back();
  if (files.size() == 2) a.sketch = files[0];
  const GDALDataType t = GDALGetDataTypeByName(a.type.c_str());
  if (t == GDT_Unknown || GDALDataTypeIsComplex(t))
    throw UsageError("-ot " + a.type + ": expected a real data type (Byte, Int16, UInt16, Int32, Float32, Float64...)");
  for (const std::string& co : a.creation_options)
    if (co.find('=') == std::string::npos || co[0] == '=')
      throw UsageError("-co expects NAME=VALUE, got '" + co + "'");
  try {
    a.terrain = gdal::parse_terrain_options(merged(a.options).List());
  } catch (const gdal::OptionError& e) {
    throw UsageError(e.what());
  }
  return a;
}

}  // namespace mcmd::cli
