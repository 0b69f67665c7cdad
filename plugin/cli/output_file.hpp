// Atomic output: write to a temporary name in the destination folder, rename
// over dst_file at the end, remove the temporary on any failure.
#pragma once

#include <string>

#include "gdal_priv.h"

namespace mcmd::cli {

class TempOutput {
 public:
  TempOutput(std::string dst, GDALDriver* driver);
  TempOutput(const TempOutput&) = delete;
  TempOutput& operator=(const TempOutput&) = delete;
  ~TempOutput();  // removes the temporary files unless commit() succeeded

  const std::string& path() const { return tmp_; }
  // Rename the (closed) temporary dataset to dst, replacing it. Throws Failure.
  void commit();

 private:
  void discard();
  std::string dst_;
  std::string tmp_;
  GDALDriver* driver_;
  bool committed_ = false;
};

}  // namespace mcmd::cli
