// The output copy of a small raster, made on a helper thread while the fill
// reads the source and solves. Made first, the copy (decode, write) left one
// of the cores idle for a tenth of a 1201² fill; the fill only needs the copy
// when it writes its filled cells, at the end.
#pragma once

#include <atomic>
#include <exception>
#include <functional>
#include <string>
#include <thread>

#include "cpl_string.h"
#include "dataset.hpp"
#include "gdal_priv.h"

namespace mcmd::cli {

class BackgroundCopy {
 public:
  // Starts copying `source_path` (opened again, read-only: GDAL datasets are
  // not shared between threads) to `path` with `driver` and `co`.
  // `keep_going` is polled by the copy's progress (from the helper thread).
  BackgroundCopy(GDALDriver* driver, std::string source_path, std::string path, CPLStringList co,
                 std::string shown, std::function<bool()> keep_going);
  BackgroundCopy(const BackgroundCopy&) = delete;
  BackgroundCopy& operator=(const BackgroundCopy&) = delete;
  ~BackgroundCopy();  // an unfinished copy is stopped; either way the thread is joined

  // Waits for the copy and returns it, open for update, its band info
  // (copy_band_info) set. Rethrows what the copy threw (create_copy's
  // gdal::Failure: "cannot write ...", or cancelled).
  GDALDataset& dataset();

  // dataset(), then closes it (flushing).
  void close();

 private:
  void run();

  GDALDriver* driver_;
  std::string source_path_, path_, shown_;
  CPLStringList co_;
  std::function<bool()> keep_going_;
  std::atomic<bool> stop_{false};
  DatasetPtr out_;
  std::exception_ptr failed_;
  std::thread thread_;
};

}  // namespace mcmd::cli
