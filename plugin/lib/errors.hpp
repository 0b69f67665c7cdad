// Internal errors of the GDAL glue, turned into CPLError at the C API.
#pragma once

#include <stdexcept>
#include <string>

#include "cpl_error.h"

namespace mcmd::gdal {

// A failure with a GDAL error number; what() is one line for the user.
class Failure : public std::runtime_error {
 public:
  Failure(CPLErrorNum num, const std::string& msg) : std::runtime_error(msg), num_(num) {}
  CPLErrorNum num() const { return num_; }

 private:
  CPLErrorNum num_;
};

// Throws Failure(CPLE_FileIO, "<what>: <GDAL's last error message>") unless
// err is CE_None: the one form of every band read or write failure.
void check_io(CPLErr err, const char* what);

// A warning for the user (not an error): CPLError(CE_Warning) with the text
// prefixed by kWarningPrefix, which the CLI prints as its own warning line.
constexpr const char* kWarningPrefix = "mcmd: ";
void warn(const std::string& msg);

// Run `body`, turning every exception into one CPLError(CE_Failure, ...).
// Returns CE_None when body returns normally.
template <class Body>
CPLErr guarded(Body&& body);

// Report the exception currently being handled through CPLError.
void report_current_exception();

template <class Body>
CPLErr guarded(Body&& body) {
  try {
    body();
    return CE_None;
  } catch (...) {
    report_current_exception();
    return CE_Failure;
  }
}

}  // namespace mcmd::gdal
