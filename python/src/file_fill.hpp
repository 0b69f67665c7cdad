// mcmd.fill_file(): mcmd_fillnodata's own code (cli/args.hpp, cli/run.hpp)
// run in the calling process, not a subprocess.
#pragma once

#include <string>
#include <vector>

#include "mcmd/progress.hpp"

namespace mcmd::python {

// Fill `src` into `dst` ("" = in place) as `mcmd_fillnodata [flags] src [dst]`
// does; `flags` are the CLI's options with their values (-b 1 -o RS=auto...),
// no file name. Progress is reported to `progress` from the calling thread.
// Throws cli::UsageError, gdal::Failure, Cancelled...: what run() throws.
void fill_file(const std::vector<std::string>& flags, const std::string& src, const std::string& dst,
               const ProgressFn& progress);

}  // namespace mcmd::python
