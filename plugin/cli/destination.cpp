#include "cli/destination.hpp"

#include <cerrno>
#include <cstring>
#include <unistd.h>

#include "cpl_conv.h"
#include "cpl_port.h"
#include "cpl_vsi.h"
#include "lib/errors.hpp"

namespace mcmd::cli {

namespace {

[[noreturn]] void refuse(const std::string& dst, const std::string& why) {
  throw gdal::Failure(CPLE_FileIO, "cannot write '" + dst + "': " + why);
}

bool is_local(const std::string& path) { return !STARTS_WITH(path.c_str(), "/vsi"); }

}  // namespace

std::string folder_of(const std::string& dst) {
  const std::string dir = CPLGetPath(dst.c_str());
  return dir.empty() ? "." : dir;
}

void check_destination(const std::string& dst) {
  VSIStatBufL st;
  if (VSIStatL(dst.c_str(), &st) == 0 && VSI_ISDIR(st.st_mode))
    refuse(dst, "it is a folder (give a file name, e.g. '" +
                    std::string(CPLFormFilename(dst.c_str(), "filled.tif", nullptr)) + "')");
  const std::string dir = folder_of(dst);
  if (VSIStatL(dir.c_str(), &st) != 0) refuse(dst, "folder '" + dir + "' does not exist");
  if (!VSI_ISDIR(st.st_mode)) refuse(dst, "'" + dir + "' is not a folder");
  if (is_local(dir) && ::access(dir.c_str(), W_OK | X_OK) != 0)
    refuse(dst, "cannot create files in folder '" + dir + "': " + std::strerror(errno));
}

}  // namespace mcmd::cli
