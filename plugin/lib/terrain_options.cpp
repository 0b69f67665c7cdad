#include "lib/terrain_options.hpp"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <functional>
#include <map>
#include <set>

#include "cpl_string.h"
#include "lib/options.hpp"

namespace mcmd::gdal {

namespace {

std::string upper(const std::string& s) { return CPLString(s).toupper(); }

// The one form of a bad value's message (as options.cpp words it).
[[noreturn]] void fail(const std::string& name, const std::string& value, const std::string& want) {
  throw OptionError(CPLString().Printf("%s=%s is invalid: expected %s", name.c_str(), value.c_str(), want.c_str()));
}

double number(const std::string& name, const std::string& value, const std::string& want = "a number") {
  char* end = nullptr;
  errno = 0;
  const double v = std::strtod(value.c_str(), &end);
  if (value.empty() || end == value.c_str() || *end != '\0' || errno == ERANGE || !std::isfinite(v))
    fail(name, value, want);
  return v;
}

int integer_in(const std::string& name, const std::string& value, int lo, int hi) {
  const std::string want = "an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]";
  const double v = number(name, value, want);
  if (v != std::floor(v) || v < lo || v > hi) fail(name, value, want);
  return static_cast<int>(v);
}

bool yes_no(const std::string& name, const std::string& value) {
  const std::string v = upper(value);
  if (v == "YES" || v == "TRUE" || v == "ON" || v == "1") return true;
  if (v == "NO" || v == "FALSE" || v == "OFF" || v == "0") return false;
  fail(name, value, "YES or NO");
}

// `count` numbers separated by commas or spaces ("a,b").
std::vector<double> numbers(const std::string& name, const std::string& value, std::size_t count,
                            const std::string& want) {
  const CPLStringList parts(CSLTokenizeString2(value.c_str(), ", ", 0));
  if (static_cast<std::size_t>(parts.size()) != count) fail(name, value, want);
  std::vector<double> out;
  for (int i = 0; i < parts.size(); ++i) out.push_back(number(name, parts[i], want));
  return out;
}

std::string file_name(const std::string& name, const std::string& value) {
  if (value.empty()) fail(name, value, "a file name");
  return value;
}

// "Z" or "Z1,Z2".
std::vector<double> heights(const std::string& name, const std::string& value) {
  const CPLStringList parts(CSLTokenizeString2(value.c_str(), ", ", 0));
  return numbers(name, value, parts.size() == 2 ? 2 : 1, "Z or Z1,Z2 (the first and last point's)");
}

void set_method(TerrainOptions& o, const std::string& n, const std::string& v) {
  const std::string m = upper(v);
  TerrainParams& t = o.terrain;
  if (m == "MCMD") t.method = TerrainMethod::mcmd;
  else if (m == "PAPER") t.method = TerrainMethod::paper;
  else if (m == "PAPER-DS" || m == "PAPER_DS") t.method = TerrainMethod::paper, t.scheme = TerrainScheme::diamond_square;
  else if (m == "PAPER-TE" || m == "PAPER_TE") t.method = TerrainMethod::paper, t.scheme = TerrainScheme::triangle_edge;
  else if (m == "MDI") t.method = TerrainMethod::mdi;
  else if (m == "NONE") t.method = TerrainMethod::none;
  else fail(n, v, "mcmd, paper, paper-ds, paper-te, mdi or none");
}

void set_scheme(TerrainOptions& o, const std::string& n, const std::string& v) {
  const std::string s = upper(v);
  if (s == "DS" || s == "DIAMOND-SQUARE") o.terrain.scheme = TerrainScheme::diamond_square;
  else if (s == "TE" || s == "TRIANGLE-EDGE") o.terrain.scheme = TerrainScheme::triangle_edge;
  else if (s == "BUTTERFLY") o.terrain.scheme = TerrainScheme::butterfly;
  else fail(n, v, "ds, te or butterfly");
}

void set_unknown(TerrainOptions& o, const std::string& n, const std::string& v) {
  const std::string u = upper(v);
  o.unknown_white = false;
  if (u == "NONE") {
    o.unknown = UnknownRule::none;
    return;
  }
  o.unknown = UnknownRule::value;
  if (u == "WHITE") o.unknown_white = true;
  else if (u == "BLACK") o.unknown_value = 0.0;
  else o.unknown_value = number(n, v, "white, black, none or a number");
}

void set_zrange(TerrainOptions& o, const std::string& n, const std::string& v) {
  const std::vector<double> r = numbers(n, v, 2, "MIN,MAX (two numbers)");
  if (r[0] >= r[1]) fail(n, v, "MIN,MAX with MIN below MAX");
  o.has_zrange = true;
  o.z_min = r[0];
  o.z_max = r[1];
}

void set_peaks(TerrainOptions& o, const std::string& n, const std::string& v) {
  if (upper(v) == "IIZUKA" || upper(v) == "TABLE1") {
    o.peaks = "iizuka";
    return;
  }
  o.peaks = std::to_string(integer_in(n, v, 1, 1000));
}

// "col,row,z;col,row,z;..."
void set_points(TerrainOptions& o, const std::string& n, const std::string& v) {
  const CPLStringList items(CSLTokenizeString2(v.c_str(), ";", 0));
  if (items.size() == 0) fail(n, v, "col,row,z[;col,row,z...]");
  for (int i = 0; i < items.size(); ++i) {
    const std::vector<double> p = numbers(n, items[i], 3, "col,row,z[;col,row,z...]");
    if (p[0] != std::floor(p[0]) || p[1] != std::floor(p[1]) || std::fabs(p[0]) > 1e9 || std::fabs(p[1]) > 1e9)
      fail(n, items[i], "whole column and row numbers");
    o.points.push_back({static_cast<int>(p[0]), static_cast<int>(p[1]), p[2]});
  }
}

void set_erosion(TerrainOptions& o, const std::string& n, const std::string& v) {
  const std::string u = upper(v);
  o.has_erosion = true;
  if (u == "AUTO" || u == "YES") o.erosion.steps = kErodeAuto;
  else if (u == "NO" || u == "NONE") o.erosion.steps = 0;
  else o.erosion.steps = integer_in(n, v, 0, kMaxErodeSteps);
}

// "K,m,n", K a number > 0 or auto.
void set_erosion_law(TerrainOptions& o, const std::string& n, const std::string& v) {
  const std::string want = "K,m,n (K > 0 or auto, m in [0, 2], n in [0.5, 4]; e.g. auto,0.5,1)";
  const CPLStringList parts(CSLTokenizeString2(v.c_str(), ", ", 0));
  if (parts.size() != 3) fail(n, v, want);
  const bool automatic = upper(parts[0]) == "AUTO";
  const double K = automatic ? 0.0 : number(n, parts[0], want);
  const double m = number(n, parts[1], want), e = number(n, parts[2], want);
  if ((!automatic && !(K > 0)) || m < 0 || m > 2 || e < 0.5 || e > 4) fail(n, v, want);
  o.erosion.K = K;
  o.erosion.m = m;
  o.erosion.n = e;
}

void set_uplift(TerrainOptions& o, const std::string& n, const std::string& v) {
  const std::string u = upper(v);
  if (u == "TERRAIN") o.erosion.uplift = UpliftPattern::terrain, o.uplift_file.clear();
  else if (u == "UNIFORM") o.erosion.uplift = UpliftPattern::uniform, o.uplift_file.clear();
  else o.erosion.uplift = UpliftPattern::map, o.uplift_file = file_name(n, v);
}

using Setter = std::function<void(TerrainOptions&, const std::string&, const std::string&)>;

const std::map<std::string, Setter>& setters() {
  static const std::map<std::string, Setter> table = {
      {"METHOD", set_method},
      {"SCHEME", set_scheme},
      {"SHARPNESS",
       [](TerrainOptions& o, auto& n, auto& v) {
         o.terrain.sharpness = number(n, v, "a number in [0, 10]");
         if (o.terrain.sharpness < 0 || o.terrain.sharpness > 10) fail(n, v, "a number in [0, 10]");
       }},
      {"UNKNOWN", set_unknown},
      {"ZRANGE", set_zrange},
      {"SKELETON", [](TerrainOptions& o, auto& n, auto& v) { o.skeleton = yes_no(n, v); }},
      {"RIDGE_COUPLES", [](TerrainOptions& o, auto& n, auto& v) { o.ridge_couples = integer_in(n, v, 1, 10000); }},
      {"RIVER_PARTICLES",
       [](TerrainOptions& o, auto& n, auto& v) { o.river_particles = integer_in(n, v, 1, 100000); }},
      {"PEAKS", set_peaks},
      {"PEAKS_NOISE", [](TerrainOptions& o, auto& n, auto& v) { o.peaks_noise = number(n, v); }},
      {"PEAKS_THRESHOLD",
       [](TerrainOptions& o, auto& n, auto& v) {
         o.peaks_threshold = number(n, v);
         o.has_peaks_threshold = true;
       }},
      {"POINTS", set_points},
      {"STATES", [](TerrainOptions& o, auto& n, auto& v) { o.states_file = file_name(n, v); }},
      {"RIDGES", [](TerrainOptions& o, auto& n, auto& v) { o.ridges = file_name(n, v); }},
      {"RIVERS", [](TerrainOptions& o, auto& n, auto& v) { o.rivers = file_name(n, v); }},
      {"RIDGE_Z", [](TerrainOptions& o, auto& n, auto& v) { o.ridge_z = heights(n, v); }},
      {"RIVER_Z", [](TerrainOptions& o, auto& n, auto& v) { o.river_z = heights(n, v); }},
      {"UPSAMPLE", [](TerrainOptions& o, auto& n, auto& v) { o.upsample = integer_in(n, v, 1, 1024); }},
      {"MEDIAN",
       [](TerrainOptions& o, auto& n, auto& v) {
         o.median = integer_in(n, v, 0, 101);
         if (o.median != 0 && (o.median < 3 || o.median % 2 == 0)) fail(n, v, "0 (none) or an odd size in [3, 101]");
       }},
      {"MEDIAN_PASSES", [](TerrainOptions& o, auto& n, auto& v) { o.median_passes = integer_in(n, v, 1, 100); }},
      {"MEDIAN_ALL", [](TerrainOptions& o, auto& n, auto& v) { o.median_all = yes_no(n, v); }},
      {"EROSION", set_erosion},
      {"EROSION_LAW", set_erosion_law},
      {"UPLIFT", set_uplift},
      {"DIFFUSION",
       [](TerrainOptions& o, auto& n, auto& v) {
         o.erosion.diffusion = number(n, v, "a factor in [0, 100]");
         if (o.erosion.diffusion < 0 || o.erosion.diffusion > 100) fail(n, v, "a factor in [0, 100]");
       }},
      {"TALUS",
       [](TerrainOptions& o, auto& n, auto& v) {
         o.erosion.talus = number(n, v, "an angle in (0, 90] degrees");
         if (!(o.erosion.talus > 0) || o.erosion.talus > 90) fail(n, v, "an angle in (0, 90] degrees");
       }},
  };
  return table;
}

// Names whose meaning is MCMDFillNodata's (parsed by options.cpp).
const std::set<std::string>& shared_names() {
  static const std::set<std::string> names = {"I",       "I_BU", "RIDGE_I", "RIDGE_I_BU", "RIVER_I",
                                              "RIVER_I_BU", "H",  "RT",      "RS",         "SEED",
                                              "DELTA",   "NUM_THREADS"};
  return names;
}

constexpr double kDefaultH = 0.7;  // rolling relief (fillnodata's 0.5 looks like gravel on a whole terrain)

}  // namespace

const char* terrain_option_names() {
  return "METHOD, SCHEME, SHARPNESS, RS, H, RT, SEED, I, I_BU, RIDGE_I, RIDGE_I_BU, RIVER_I, RIVER_I_BU, DELTA, "
         "UNKNOWN, ZRANGE, SKELETON, RIDGE_COUPLES, RIVER_PARTICLES, PEAKS, PEAKS_NOISE, PEAKS_THRESHOLD, POINTS, "
         "STATES, RIDGES, RIVERS, RIDGE_Z, RIVER_Z, UPSAMPLE, MEDIAN, MEDIAN_PASSES, MEDIAN_ALL, EROSION, EROSION_LAW, "
         "UPLIFT, DIFFUSION, TALUS, NUM_THREADS";
}

int erosion_steps(const TerrainOptions& o, bool has_sketch) {
  if (o.has_erosion) return o.erosion.steps;
  if (o.terrain.method == TerrainMethod::none || has_sketch || !o.peaks.empty() || !o.points.empty()) return 0;
  return kErodeAuto;
}

TerrainOptions parse_terrain_options(CSLConstList options) {
  TerrainOptions out;
  CPLStringList shared;
  shared.AddNameValue("H", CPLSPrintf("%.17g", kDefaultH));
  for (CSLConstList p = options; p && *p; ++p) {
    const std::string item = *p;
    const std::size_t eq = item.find('=');
    if (eq == std::string::npos || eq == 0)
      throw OptionError("option '" + item + "' is not of the form NAME=VALUE");
    const std::string name = upper(item.substr(0, eq)), value = item.substr(eq + 1);
    if (shared_names().count(name)) {
      shared.SetNameValue(name.c_str(), value.c_str());
    } else if (const auto it = setters().find(name); it != setters().end()) {
      it->second(out, name, value);
    } else {
      throw OptionError("unknown option '" + item.substr(0, eq) + "' (known: " + terrain_option_names() + ")");
    }
  }
  const Options fill = parse_options(shared.List());
  const TerrainMethod method = out.terrain.method;
  const TerrainScheme scheme = out.terrain.scheme;
  const double sharpness = out.terrain.sharpness;
  out.terrain.fill = fill.fill;
  out.terrain.method = method;
  out.terrain.scheme = scheme;
  out.terrain.sharpness = sharpness;
  out.terrain.threads = fill.num_threads;
  return out;
}

}  // namespace mcmd::gdal
