// Command line of mcmd_fillnodata, parsed into plain values.
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

#include "lib/options.hpp"

namespace mcmd::cli {

// A malformed command line; what() is one line.
class UsageError : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

struct Args {
  bool help = false;
  bool version = false;
  bool quiet = false;
  bool nomask = false;
  std::vector<int> bands;                     // 1-based; empty = every band but alpha
  std::string mask_file;                      // "" = none
  std::string format;                         // "" = guess from dst_file's extension
  std::vector<std::string> creation_options;  // -co NAME=VALUE
  std::vector<std::string> fill_options;      // NAME=VALUE for MCMDFillNodata, as given
  gdal::Options fill;                         // fill_options, parsed
  std::string src;
  std::string dst;  // "" = in place
};

// Parse argv (argv[0] is skipped), the fill options included, so an absurd
// parameter is reported before any file is opened. Throws UsageError.
Args parse_args(int argc, const char* const* argv);

}  // namespace mcmd::cli
