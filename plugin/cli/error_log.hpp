// GDAL error handling for the CLI: GDAL's own messages are silenced and the
// first failure is kept, so the user sees exactly one line.
#pragma once

#include <string>

#include "cpl_error.h"

namespace mcmd::cli {

class ErrorLog {
 public:
  ErrorLog();   // installs the handler (CPLPushErrorHandlerEx)
  ~ErrorLog();  // restores the previous one
  ErrorLog(const ErrorLog&) = delete;
  ErrorLog& operator=(const ErrorLog&) = delete;

  void reset() {
    failures_ = 0;
    first_.clear();
  }
  int failures() const { return failures_; }
  const std::string& first_failure() const { return first_; }

 private:
  static void CPL_STDCALL handler(CPLErr err_class, CPLErrorNum err_no, const char* msg);
  int failures_ = 0;
  std::string first_;
};

}  // namespace mcmd::cli
