#include "cli/output_file.hpp"

#include <cerrno>
#include <cstring>
#include <unistd.h>

#include "cpl_conv.h"
#include "cpl_vsi.h"
#include "lib/errors.hpp"

namespace mcmd::cli {

namespace {

// Sidecars GDAL may write next to a dataset.
constexpr const char* kSidecars[] = {".aux.xml", ".msk", ".ovr"};

bool exists(const std::string& path) {
  VSIStatBufL st;
  return VSIStatL(path.c_str(), &st) == 0;
}

// dir/stem.mcmd-tmp-PID.ext: same folder (so rename is atomic), same extension.
std::string temp_name(const std::string& dst) {
  const std::string dir = CPLGetPath(dst.c_str());
  const std::string stem = CPLGetBasename(dst.c_str());
  const std::string ext = CPLGetExtension(dst.c_str());
  const std::string name = stem + ".mcmd-tmp-" + std::to_string(::getpid()) + (ext.empty() ? "" : "." + ext);
  return dir.empty() ? name : CPLFormFilename(dir.c_str(), name.c_str(), nullptr);
}

}  // namespace

TempOutput::TempOutput(std::string dst, GDALDriver* driver)
    : dst_(std::move(dst)), tmp_(temp_name(dst_)), driver_(driver) {}

TempOutput::~TempOutput() {
  if (!committed_) discard();
}

void TempOutput::discard() {
  CPLPushErrorHandler(CPLQuietErrorHandler);
  if (exists(tmp_)) driver_->Delete(tmp_.c_str());
  VSIUnlink(tmp_.c_str());
  for (const char* s : kSidecars) VSIUnlink((tmp_ + s).c_str());
  CPLPopErrorHandler();
}

void TempOutput::commit() {
  for (const char* s : kSidecars)
    if (!exists(tmp_ + s) && exists(dst_ + s)) VSIUnlink((dst_ + s).c_str());
  CPLErrorReset();
  errno = 0;
  if (driver_->Rename(dst_.c_str(), tmp_.c_str()) != CE_None) {
    const std::string gdal_says = CPLGetLastErrorMsg();
    const std::string why = !gdal_says.empty() ? gdal_says : errno ? std::strerror(errno) : "unknown reason";
    throw gdal::Failure(CPLE_FileIO, "cannot rename the temporary output to '" + dst_ + "': " + why);
  }
  committed_ = true;
}

}  // namespace mcmd::cli
