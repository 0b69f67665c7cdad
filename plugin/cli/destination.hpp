// Checks on dst_file made before anything is read or filled, so that a run
// that cannot end well fails at once, with the reason.
#pragma once

#include <string>

namespace mcmd::cli {

// Throws gdal::Failure ("cannot write '<dst>': ...") when dst is a folder,
// its folder does not exist or is not writable.
void check_destination(const std::string& dst);

// The folder dst_file goes to ("." for a bare name).
std::string folder_of(const std::string& dst);

}  // namespace mcmd::cli
