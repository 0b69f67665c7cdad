#include "cli/general_options.hpp"

#include <string>

#include "cli/args.hpp"
#include "cpl_error.h"
#include "gdal.h"

namespace mcmd::cli {

std::optional<CPLStringList> apply_gdal_general_options(int argc, char** argv) {
  CPLStringList given;
  bool version = false;
  for (int i = 0; i < argc; ++i) {
    if (i > 0 && EQUAL(argv[i], "--version"))
      version = true;  // ours, not GDAL's
    else
      given.AddString(argv[i]);
  }
  // The processor leaves the list it is given alone and returns a new one
  // (the caller's to free) when it goes on.
  char** args = given.List();
  CPLErrorReset();
  const int n = GDALGeneralCmdLineProcessor(given.size(), &args, GDAL_OF_RASTER);
  if (n < 0) {
    const std::string why = CPLGetLastErrorMsg();
    throw UsageError(why.empty() ? "invalid GDAL general option (see --help-general)" : why);
  }
  if (n == 0) return std::nullopt;
  CPLStringList left(args, TRUE);
  if (version) left.AddString("--version");
  return left;
}

}  // namespace mcmd::cli
