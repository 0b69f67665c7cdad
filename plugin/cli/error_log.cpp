#include "cli/error_log.hpp"

#include "cpl_error.h"

namespace mcmd::cli {

ErrorLog::ErrorLog() { CPLPushErrorHandlerEx(&ErrorLog::handler, this); }

ErrorLog::~ErrorLog() { CPLPopErrorHandler(); }

void CPL_STDCALL ErrorLog::handler(CPLErr err_class, CPLErrorNum err_no, const char* msg) {
  if (err_class == CE_Debug) {  // only emitted when asked for (--debug on, CPL_DEBUG)
    CPLDefaultErrorHandler(err_class, err_no, msg);
    return;
  }
  if (err_class < CE_Failure) return;  // warnings stay quiet
  auto* self = static_cast<ErrorLog*>(CPLGetErrorHandlerUserData());
  if (self->failures_++ == 0 && msg) self->first_ = msg;
}

}  // namespace mcmd::cli
