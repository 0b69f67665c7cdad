// What mcmd_fillnodata does once its command line is parsed.
#pragma once

#include "cli/args.hpp"
#include "cli/error_log.hpp"
#include "gdal.h"

namespace mcmd::cli {

// Fill args.src into args.dst (or in place). Progress goes to `progress`
// (nullptr: none). Throws gdal::Failure / std::exception with a one-line
// message on any failure, after removing any temporary output.
void run(const Args& args, ErrorLog& log, GDALProgressFunc progress);

// Set by SIGINT and SIGTERM (async-signal-safe): the next progress report
// cancels the run cleanly.
void request_interrupt();
bool interrupted();

}  // namespace mcmd::cli
