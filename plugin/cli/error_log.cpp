#include "cli/error_log.hpp"

#include <cstdio>
#include <cstring>

#include "cpl_error.h"
#include "lib/errors.hpp"

namespace mcmd::cli {

ErrorLog::ErrorLog() { CPLPushErrorHandlerEx(&ErrorLog::handler, this); }

ErrorLog::~ErrorLog() { CPLPopErrorHandler(); }

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
  if (self->failures_++ == 0 && msg) self->first_ = msg;
}

}  // namespace mcmd::cli
