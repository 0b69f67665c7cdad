// --help and --version text of mcmd_fillnodata.
#pragma once

#include <string>

namespace mcmd::cli {

std::string help_text();
std::string version_text();

}  // namespace mcmd::cli
