// Every MCMDFillNodata option, parsed and validated in one place.
#pragma once

#include <stdexcept>
#include <string>

#include "cpl_port.h"
#include "mcmd/params.hpp"
#include "mcmd/raster_access.hpp"

namespace mcmd::gdal {

// A bad option: what() is one line naming the option and the accepted values.
class OptionError : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

struct Options {
  FillParams fill{};          // algorithm parameters handed to mcmd::fill
  double max_distance = 0.0;  // cells; 0 = unlimited
  int tile_size = 0;          // 2^n+1 cells; 0 = automatic (mcmd::TilingParams::tile_side)
  bool always_tile = false;   // TILING=ALWAYS (mcmd::TilingParams::always_tile)
  int num_threads = 0;        // 0 = all CPUs
  std::string rivers;         // RIVERS=: a file of river lines (lib/line_input.hpp); "" = none
  std::string ridges;         // RIDGES=: likewise, ridge lines
  std::string fill_from;      // FILL_FROM=: a second DEM (lib/fill_from.hpp); "" = none
  std::string fill_from_resampling = "cubic";  // FILL_FROM_RESAMPLING=: bilinear or cubic
  bool inner_only = false;    // INNER_ONLY=YES: leave the voids touching the border
  // MAX_VOID=: leave the voids larger than this, in cells or (max_void_in_m2)
  // in square metres; 0 = no cap. void_cap_cells() turns it into cells.
  double max_void = 0.0;
  bool max_void_in_m2 = false;
};

// The raster engine's tiling parameters of `o`.
TilingParams tiling_of(const Options& o);

// Parse NAME=VALUE strings (names case-insensitive). Throws OptionError.
Options parse_options(CSLConstList options);

// The accepted option names, comma separated (for messages and help).
const char* option_names();

}  // namespace mcmd::gdal
