// The output copy of a small raster, made on a helper thread while the fill
// reads the source and solves. Made first, the copy (decode, write) left one
// of the cores idle for a tenth of a 1201² fill; the fill only needs the copy
// when it writes its filled cells, at the end. The same thread closes it:
// writing the georeferencing looks the CRS up in PROJ's database, which the
// helper's PROJ context (one per thread) has open and cached from the copy;
// on the main thread that was ~7 ms more at the end of a 1027×875 fill.
// A single-band source is copied blank (blank_source.hpp): the fill, which
// holds all its cells, writes every cell of the copy, and the source is
// decoded once.
#pragma once

#include <atomic>
#include <condition_variable>
#include <exception>
#include <functional>
#include <mutex>
#include <string>
#include <thread>

#include "cli/dataset.hpp"
#include "cpl_string.h"
#include "gdal_priv.h"

namespace mcmd::cli {

class BackgroundCopy {
 public:
  // Starts copying `source_path` (opened again, read-only: GDAL datasets are
  // not shared between threads) to `path` with `driver` and `co`.
  // `keep_going` is polled by the copy's progress (from the helper thread).
  // With `blank` (a single-band source), the copy's band is left for the fill
  // to write whole (FillRequest::blank_target).
  BackgroundCopy(GDALDriver* driver, std::string source_path, std::string path, CPLStringList co,
                 std::string shown, std::function<bool()> keep_going, bool blank);
  BackgroundCopy(const BackgroundCopy&) = delete;
  BackgroundCopy& operator=(const BackgroundCopy&) = delete;
  ~BackgroundCopy();  // an unfinished copy is stopped; either way the thread is joined

  // Whether the copy's band is blank: the fill must write every cell.
  bool blank() const { return blank_; }

  // Waits for the copy and returns it, open for update, its band info
  // (copy_band_info) set. Rethrows what the copy threw (create_copy's
  // gdal::Failure: "cannot write ...", or cancelled).
  GDALDataset& dataset();

  // dataset(), then has the helper close it (flushing). Rethrows a failure
  // to write ("cannot write ...").
  void close();

 private:
  enum class Stage { copying, made, closing };  // made: out_, or failed_
  void run();
  void advance(Stage to);

  GDALDriver* driver_;
  std::string source_path_, path_, shown_;
  CPLStringList co_;
  std::function<bool()> keep_going_;
  bool blank_;
  std::atomic<bool> stop_{false};
  std::mutex mutex_;
  std::condition_variable changed_;
  Stage stage_ = Stage::copying;
  DatasetPtr out_;
  std::exception_ptr failed_;
  std::thread thread_;
};

}  // namespace mcmd::cli
