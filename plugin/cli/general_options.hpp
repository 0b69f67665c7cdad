// GDAL's general command-line options (--config KEY VALUE, --debug on,
// --formats, --format NAME, --help-general, --optfile FILE, ...), handled as
// every GDAL utility handles them: by GDALGeneralCmdLineProcessor, before
// mcmd_fillnodata's own options are parsed. Our --version is kept (GDAL's
// would print only GDAL's version).
#pragma once

#include <optional>

#include "cpl_string.h"

namespace mcmd::cli {

// The command line left once GDAL's general options are applied (argv[0]
// first), or nothing when one of them asked to stop after printing (e.g.
// --formats). Throws UsageError with GDAL's message (e.g. --config without
// a value).
std::optional<CPLStringList> apply_gdal_general_options(int argc, char** argv);

}  // namespace mcmd::cli
