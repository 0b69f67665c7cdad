#include "cli/error_log.hpp"

#include <cstdio>
#include <cstring>
#include <string>

#include "cpl_error.h"
#include "lib/errors.hpp"

namespace mcmd::cli {

namespace {

// GDAL's decode threads name the in-memory copy of a block they decode
// ("/vsimem/decompress_0x....tif: ..."): a name that means nothing to the user.
std::string without_internal_name(const char* msg) {
  constexpr const char* kInternal = "/vsimem/";
  if (std::strncmp(msg, kInternal, std::strlen(kInternal)) != 0) return msg;
  const char* colon = std::strchr(msg, ':');
  if (!colon) return msg;
  return colon[1] == ' ' ? colon + 2 : colon + 1;
}

}  // namespace

ErrorLog::ErrorLog(Reach reach) : reach_(reach) {
  CPLPushErrorHandlerEx(&ErrorLog::handler, this);
  if (reach_ == Reach::every_thread) previous_global_ = CPLSetErrorHandlerEx(&ErrorLog::handler, this);
}

ErrorLog::~ErrorLog() {
  if (reach_ == Reach::every_thread) CPLSetErrorHandlerEx(previous_global_, nullptr);
  CPLPopErrorHandler();
}

void ErrorLog::reset() {
  const std::lock_guard lock(mutex_);
  failures_ = 0;
  first_.clear();
}

int ErrorLog::failures() const {
  const std::lock_guard lock(mutex_);
  return failures_;
}

std::string ErrorLog::first_failure() const {
  const std::lock_guard lock(mutex_);
  return first_;
}

void CPL_STDCALL ErrorLog::handler(CPLErr err_class, CPLErrorNum err_no, const char* msg) {
  if (err_class == CE_Debug) {  // only emitted when asked for (--debug on, CPL_DEBUG)
    CPLDefaultErrorHandler(err_class, err_no, msg);
    return;
  }
  if (err_class == CE_Warning && msg && std::strncmp(msg, gdal::kWarningPrefix, std::strlen(gdal::kWarningPrefix)) == 0) {
    std::fprintf(stderr, "mcmd_fillnodata: warning: %s\n", msg + std::strlen(gdal::kWarningPrefix));
    return;
  }
  if (err_class < CE_Failure) return;  // GDAL's warnings stay quiet
  auto* self = static_cast<ErrorLog*>(CPLGetErrorHandlerUserData());
  const std::lock_guard lock(self->mutex_);
  if (self->failures_++ == 0 && msg) self->first_ = without_internal_name(msg);
}

}  // namespace mcmd::cli
