#include "cli/args.hpp"

#include <cstdlib>
#include <map>

#include "cpl_string.h"

namespace mcmd::cli {

namespace {

// Flags that are shorthands for one MCMDFillNodata option.
const std::map<std::string, std::string>& option_flags() {
  static const std::map<std::string, std::string> table = {
      {"-md", "MAX_DISTANCE"}, {"-method", "METHOD"}, {"-delta", "DELTA"}, {"-I", "I"},
      {"-Ibu", "I_BU"},        {"-H", "H"},           {"-rt", "RT"},       {"-rs", "RS"},
      {"-seed", "SEED"},       {"-morph", "MORPH"},       {"-rivers", "RIVERS"},  {"-ridges", "RIDGES"},
      {"-maxvoid", "MAX_VOID"}, {"-fill-from", "FILL_FROM"},       {"-tile", "TILE_SIZE"}, {"-threads", "NUM_THREADS"},
  };
  return table;
}

int band_number(const std::string& s) {
  const bool digits = !s.empty() && s.size() <= 7 && s.find_first_not_of("0123456789") == std::string::npos;
  const long v = digits ? std::strtol(s.c_str(), nullptr, 10) : 0;
  if (v < 1 || v > 1000000)
    throw UsageError("-b expects a band number >= 1, got '" + s + "'");
  return static_cast<int>(v);
}

class Reader {
 public:
  Reader(int argc, const char* const* argv) : argc_(argc), argv_(argv) {}
  bool done() const { return i_ >= argc_; }
  std::string next() { return argv_[i_++]; }
  std::string value_of(const std::string& flag) {
    if (done()) throw UsageError(flag + " expects a value");
    return next();
  }

 private:
  int argc_;
  const char* const* argv_;
  int i_ = 1;
};

void add_positional(Args& a, const std::string& s) {
  if (a.src.empty())
    a.src = s;
  else if (a.dst.empty())
    a.dst = s;
  else
    throw UsageError("too many file names: '" + s + "' (expected src_file [dst_file])");
}

// Handle one flag; false when `flag` is not one of ours.
bool handle_flag(Args& a, const std::string& flag, Reader& in) {
  if (flag == "--help" || flag == "-h" || flag == "-help") a.help = true;
  else if (flag == "--version") a.version = true;
  else if (flag == "-q" || flag == "-quiet") a.quiet = true;
  else if (flag == "-nomask") a.nomask = true;
  else if (flag == "-inner") a.fill_options.push_back("INNER_ONLY=YES");
  else if (flag == "-b") a.bands.push_back(band_number(in.value_of(flag)));
  else if (flag == "-mask") a.mask_file = in.value_of(flag);
  else if (flag == "-of") a.format = in.value_of(flag);
  else if (flag == "-co") a.creation_options.push_back(in.value_of(flag));
  else if (flag == "-o") a.fill_options.push_back(in.value_of(flag));
  else if (auto it = option_flags().find(flag); it != option_flags().end())
    a.fill_options.push_back(it->second + "=" + in.value_of(flag));
  else return false;
  return true;
}

}  // namespace

Args parse_args(int argc, const char* const* argv) {
  Args a;
  Reader in(argc, argv);
  while (!in.done()) {
    const std::string s = in.next();
    if (s.size() > 1 && s[0] == '-') {
      if (!handle_flag(a, s, in)) throw UsageError("unknown option '" + s + "' (see --help)");
    } else {
      add_positional(a, s);
    }
  }
  if (a.help || a.version) return a;
  if (a.src.empty()) throw UsageError("missing src_file (usage: mcmd_fillnodata [options] src_file [dst_file])");
  for (const std::string& co : a.creation_options)
    if (co.find('=') == std::string::npos || co[0] == '=')
      throw UsageError("-co expects NAME=VALUE, got '" + co + "'");
  CPLStringList opts;
  for (const std::string& o : a.fill_options) opts.AddString(o.c_str());
  try {
    a.fill = gdal::parse_options(opts.List());
  } catch (const gdal::OptionError& e) {
    throw UsageError(e.what());
  }
  return a;
}

}  // namespace mcmd::cli
