// GDAL error handling for the CLI: GDAL's own messages are silenced and the
// first failure is kept, so the user sees exactly one line.
#pragma once

#include <mutex>
#include <string>

#include "cpl_error.h"

namespace mcmd::cli {

class ErrorLog {
 public:
  // Whose errors it takes: this thread's (GDAL's handler stack is per
  // thread), or also those of threads with no handler of their own, such as
  // GDAL's decode threads (GDAL_NUM_THREADS), through the process-wide
  // handler. The tool's main log takes every thread's.
  enum class Reach { this_thread, every_thread };

  explicit ErrorLog(Reach reach = Reach::this_thread);  // installs the handler
  ~ErrorLog();                                           // restores the previous one(s)
  ErrorLog(const ErrorLog&) = delete;
  ErrorLog& operator=(const ErrorLog&) = delete;

  void reset();
  int failures() const;
  std::string first_failure() const;

 private:
  static void CPL_STDCALL handler(CPLErr err_class, CPLErrorNum err_no, const char* msg);
  Reach reach_;
  CPLErrorHandler previous_global_ = nullptr;
  mutable std::mutex mutex_;  // errors may come from several threads at once
  int failures_ = 0;
  std::string first_;
};

}  // namespace mcmd::cli
