#include "lib/options.hpp"

#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <functional>
#include <map>
#include <string>

#include "cpl_string.h"

namespace mcmd::gdal {

namespace {

std::string upper(std::string s) {
  for (char& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return s;
}

[[noreturn]] void fail(const std::string& name, const std::string& value, const std::string& want) {
  throw OptionError(name + "=" + value + " is invalid: expected " + want);
}

// A decimal number as people write one: [+-]digits[.digits][e[+-]digits]
// (either side of the point may be empty, not both). strtod alone also took
// hexadecimal (0x10), inf, nan and leading blanks.
bool is_decimal(const std::string& v) {
  std::size_t i = 0;
  const auto digits = [&] {
    const std::size_t from = i;
    while (i < v.size() && std::isdigit(static_cast<unsigned char>(v[i]))) ++i;
    return i - from;
  };
  if (i < v.size() && (v[i] == '+' || v[i] == '-')) ++i;
  std::size_t mantissa = digits();
  if (i < v.size() && v[i] == '.') {
    ++i;
    mantissa += digits();
  }
  if (mantissa == 0) return false;
  if (i < v.size() && (v[i] == 'e' || v[i] == 'E')) {
    ++i;
    if (i < v.size() && (v[i] == '+' || v[i] == '-')) ++i;
    if (digits() == 0) return false;
  }
  return i == v.size();
}

double number(const std::string& name, const std::string& value) {
  if (!is_decimal(value)) fail(name, value, "a decimal number");
  const char* s = value.c_str();
  char* end = nullptr;
  errno = 0;
  const double v = std::strtod(s, &end);
  if (value.empty() || end == s || *end != '\0' || errno == ERANGE || !std::isfinite(v))
    fail(name, value, "a number");
  return v;
}

double number_in(const std::string& name, const std::string& value, double lo, double hi) {
  const double v = number(name, value);
  if (v < lo || v > hi)
    fail(name, value, "a number in [" + CPLString().Printf("%g", lo) + ", " +
                          CPLString().Printf("%g", hi) + "]");
  return v;
}

std::uint64_t unsigned_integer(const std::string& name, const std::string& value) {
  if (value.empty() || value.find_first_not_of("0123456789") != std::string::npos)
    fail(name, value, "a non-negative integer");
  errno = 0;
  const unsigned long long v = std::strtoull(value.c_str(), nullptr, 10);
  if (errno == ERANGE) fail(name, value, "an integer below 2^64");
  return v;
}

bool is_tile_size(std::uint64_t v) {
  if (v < 3 || v > (1u << 15) + 1) return false;
  const std::uint64_t p = v - 1;
  return (p & (p - 1)) == 0;
}

Method method_of(const std::string& name, const std::string& value) {
  const std::string v = upper(value);
  if (v == "MCMD") return Method::mcmd;
  if (v == "PAPER-DS" || v == "PAPER_DS") return Method::paper_ds;
  if (v == "PAPER-TE" || v == "PAPER_TE") return Method::paper_te;
  fail(name, value, "mcmd, paper-ds or paper-te");
}

DeltaForm delta_of(const std::string& name, const std::string& value) {
  const std::string v = upper(value);
  if (v == "NORMALIZED") return DeltaForm::normalized;
  if (v == "PAPER") return DeltaForm::paper;
  fail(name, value, "normalized or paper");
}

// RS: auto, a fraction of the known elevation range, or an amplitude in
// elevation units with the suffix m ("300m": rs 1 of a 300 m unit).
void set_roughness(FillParams& f, const std::string& name, const std::string& value) {
  f.rs_auto = upper(value) == "AUTO";
  if (f.rs_auto) return;
  if (value.size() > 1 && (value.back() == 'm' || value.back() == 'M')) {
    const double amplitude = number(name, value.substr(0, value.size() - 1));
    if (amplitude < 0 || amplitude > 1e7)
      fail(name, value, "auto, a fraction in [0, 10] or an amplitude in [0m, 10000000m]");
    f.rs = amplitude > 0 ? 1.0 : 0.0;
    f.noise_unit = amplitude;
    return;
  }
  f.rs = number_in(name, value, 0.0, 10.0);
  f.noise_unit = 0.0;
}

bool yes_no(const std::string& name, const std::string& value) {
  const std::string v = upper(value);
  if (v == "YES" || v == "TRUE" || v == "ON" || v == "1") return true;
  if (v == "NO" || v == "FALSE" || v == "OFF" || v == "0") return false;
  fail(name, value, "YES or NO");
}

// MAX_VOID: a number of cells ("5000", "5000cells") or an area with its unit
// ("40000m2", "2.5km2", "4ha").
void set_max_void(Options& o, const std::string& name, const std::string& value) {
  static const struct {
    const char* suffix;
    double m2;  // 0: cells
  } units[] = {{"CELLS", 0.0}, {"KM2", 1e6}, {"HA", 1e4}, {"M2", 1.0}};
  const std::string v = upper(value);
  std::string digits = value;
  double scale = 0.0;
  for (const auto& u : units) {
    const std::string s = u.suffix;
    if (v.size() > s.size() && v.compare(v.size() - s.size(), s.size(), s) == 0) {
      digits = value.substr(0, v.size() - s.size());
      scale = u.m2;
      break;
    }
  }
  const char* want = "a whole number of cells (5000, 5000cells) or an area (40000m2, 2.5km2, 4ha), >= 0";
  if (!is_decimal(digits)) fail(name, value, want);
  const double n = number(name, digits);
  if (n < 0 || n > 1e18 || (scale == 0 && n != std::floor(n))) fail(name, value, want);
  o.max_void_in_m2 = scale > 0 && n > 0;
  o.max_void = scale > 0 ? n * scale : n;
}

std::string path_of(const std::string& name, const std::string& value) {
  if (value.empty()) fail(name, value, "a file name");
  return value;
}

// |I| beyond this makes Δ a step function: surely a typo.
constexpr double kMaxShape = 100.0;

using Setter = std::function<void(Options&, const std::string& name, const std::string& value)>;

Setter shape(double StateShape::*member, StateShape FillParams::*state) {
  return [=](Options& o, const std::string& n, const std::string& v) {
    (o.fill.*state).*member = number_in(n, v, -kMaxShape, kMaxShape);
  };
}

const std::map<std::string, Setter>& setters() {
  static const std::map<std::string, Setter> table = {
      {"METHOD", [](Options& o, auto& n, auto& v) { o.fill.method = method_of(n, v); }},
      {"DELTA", [](Options& o, auto& n, auto& v) { o.fill.delta_form = delta_of(n, v); }},
      {"I", shape(&StateShape::I, &FillParams::known_shape)},
      {"I_BU", shape(&StateShape::I_bu, &FillParams::known_shape)},
      {"RIDGE_I", shape(&StateShape::I, &FillParams::ridge_shape)},
      {"RIDGE_I_BU", shape(&StateShape::I_bu, &FillParams::ridge_shape)},
      {"RIVER_I", shape(&StateShape::I, &FillParams::river_shape)},
      {"RIVER_I_BU", shape(&StateShape::I_bu, &FillParams::river_shape)},
      {"H", [](Options& o, auto& n, auto& v) { o.fill.H = number_in(n, v, 0.0, 1.0); }},
      {"RT", [](Options& o, auto& n, auto& v) { o.fill.rt = number_in(n, v, -1.0, 1.0); }},
      {"RS", [](Options& o, auto& n, auto& v) { set_roughness(o.fill, n, v); }},
      {"SEED", [](Options& o, auto& n, auto& v) { o.fill.seed = unsigned_integer(n, v); }},
      {"MORPH",
       [](Options& o, auto& n, auto& v) {
         const std::string m = upper(v);
         if (m != "NONE" && m != "AUTO") fail(n, v, "none or auto");
         o.fill.morph.channels = m == "AUTO";
       }},
      {"MORPH_CHANNEL", [](Options& o, auto& n, auto& v) { o.fill.morph.min_inflow = number_in(n, v, 1.0, 1e15); }},
      {"RIVERS", [](Options& o, auto& n, auto& v) { o.rivers = path_of(n, v); }},
      {"RIDGES", [](Options& o, auto& n, auto& v) { o.ridges = path_of(n, v); }},
      {"FILL_FROM", [](Options& o, auto& n, auto& v) { o.fill_from = path_of(n, v); }},
      {"FILL_FROM_RESAMPLING",
       [](Options& o, auto& n, auto& v) {
         const std::string r = upper(v);
         if (r != "BILINEAR" && r != "CUBIC") fail(n, v, "bilinear or cubic");
         o.fill_from_resampling = r == "CUBIC" ? "cubic" : "bilinear";
       }},
      {"INNER_ONLY", [](Options& o, auto& n, auto& v) { o.inner_only = yes_no(n, v); }},
      {"MAX_VOID", set_max_void},
      {"MAX_DISTANCE",
       [](Options& o, auto& n, auto& v) { o.max_distance = number_in(n, v, 0.0, 1e12); }},
      {"TILE_SIZE",
       [](Options& o, auto& n, auto& v) {
         const std::uint64_t t = unsigned_integer(n, v);
         if (t != 0 && !is_tile_size(t)) fail(n, v, "0 (automatic) or 2^n+1 between 3 and 32769");
         o.tile_size = static_cast<int>(t);
       }},
      {"TILING",
       [](Options& o, auto& n, auto& v) {
         const std::string t = upper(v);
         if (t != "AUTO" && t != "ALWAYS") fail(n, v, "AUTO or ALWAYS");
         o.always_tile = t == "ALWAYS";
       }},
      {"NUM_THREADS",
       [](Options& o, auto& n, auto& v) {
         if (upper(v) == "ALL_CPUS") {
           o.num_threads = 0;
           return;
         }
         const std::uint64_t t = unsigned_integer(n, v);
         if (t < 1 || t > 1024) fail(n, v, "ALL_CPUS or an integer in [1, 1024]");
         o.num_threads = static_cast<int>(t);
       }},
  };
  return table;
}

}  // namespace

const char* option_names() {
  return "METHOD, DELTA, I, I_BU, RIDGE_I, RIDGE_I_BU, RIVER_I, RIVER_I_BU, H, RT, RS, SEED, MORPH, "
         "MORPH_CHANNEL, RIVERS, RIDGES, MAX_DISTANCE, INNER_ONLY, MAX_VOID, FILL_FROM, FILL_FROM_RESAMPLING, TILE_SIZE, TILING, NUM_THREADS";
}

TilingParams tiling_of(const Options& o) {
  TilingParams t;
  t.tile_side = o.tile_size;
  t.always_tile = o.always_tile;
  t.threads = o.num_threads;
  t.max_distance = o.max_distance;
  t.inner_only = o.inner_only;
  t.max_void_cells = o.max_void_in_m2 ? 0 : static_cast<std::size_t>(o.max_void);
  return t;
}

Options parse_options(CSLConstList options) {
  Options out;
  for (CSLConstList p = options; p && *p; ++p) {
    const std::string item = *p;
    const std::size_t eq = item.find('=');
    if (eq == std::string::npos || eq == 0)
      throw OptionError("option '" + item + "' is not of the form NAME=VALUE");
    const std::string name = upper(item.substr(0, eq));
    const std::string value = item.substr(eq + 1);
    const auto it = setters().find(name);
    if (it == setters().end())
      throw OptionError("unknown option '" + item.substr(0, eq) + "' (known: " + option_names() + ")");
    it->second(out, name, value);
  }
  return out;
}

}  // namespace mcmd::gdal
