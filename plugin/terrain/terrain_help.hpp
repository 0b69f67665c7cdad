// mcmd_terrain --help and --version.
#pragma once

#include <string>

namespace mcmd::cli {

std::string terrain_help_text();
std::string terrain_version_text();

}  // namespace mcmd::cli
