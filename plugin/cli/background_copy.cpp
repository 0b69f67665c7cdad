#include "cli/background_copy.hpp"

#include <algorithm>
#include <memory>
#include <utility>

#include "cli/error_log.hpp"
#include "lib/blank_source.hpp"
#include "lib/errors.hpp"

namespace mcmd::cli {

BackgroundCopy::BackgroundCopy(GDALDriver* driver, std::string source_path, std::string path, CPLStringList co,
                               std::string shown, std::function<bool()> keep_going, bool blank)
    : driver_(driver),
      source_path_(std::move(source_path)),
      path_(std::move(path)),
      shown_(std::move(shown)),
      co_(std::move(co)),
      keep_going_(std::move(keep_going)),
      blank_(blank),
      thread_(&BackgroundCopy::run, this) {}

BackgroundCopy::~BackgroundCopy() {
  stop_ = true;
  advance(Stage::closing);
  if (thread_.joinable()) thread_.join();
}

void BackgroundCopy::advance(Stage to) {
  {
    const std::lock_guard lock(mutex_);
    stage_ = std::max(stage_, to);
  }
  changed_.notify_all();
}

void BackgroundCopy::run() {
  ErrorLog log;  // this thread's GDAL errors, quietly (the handler stack is per thread)
  const auto progress = [](double, const char*, void* self) -> int {
    auto* copy = static_cast<BackgroundCopy*>(self);
    return !copy->stop_ && copy->keep_going_();
  };
  try {
    DatasetPtr src(GDALDataset::Open(source_path_.c_str(), GDAL_OF_RASTER | GDAL_OF_READONLY));
    if (!src) throw gdal::Failure(CPLE_FileIO, "cannot write '" + shown_ + "': cannot reopen the source");
    const std::unique_ptr<GDALDataset> view = blank_ ? gdal::blank_source(*src) : nullptr;
    DatasetPtr out = create_copy(driver_, path_, view ? *view : *src, co_.List(), log, progress, this, shown_);
    out = reopen_for_update(std::move(out), path_, shown_);
    if (log.failures() != 0) throw gdal::Failure(CPLE_FileIO, "cannot write '" + shown_ + "': " + log.first_failure());
    copy_band_info(*src, *out);
    out_ = std::move(out);
  } catch (...) {
    failed_ = std::current_exception();
  }
  advance(Stage::made);
  {
    std::unique_lock lock(mutex_);
    changed_.wait(lock, [this] { return stage_ == Stage::closing; });
  }
  if (!out_) return;
  log.reset();
  out_.reset();  // flushes
  if (log.failures() != 0)
    failed_ = std::make_exception_ptr(
        gdal::Failure(CPLE_FileIO, "cannot write '" + shown_ + "': " + log.first_failure()));
}

GDALDataset& BackgroundCopy::dataset() {
  {
    std::unique_lock lock(mutex_);
    changed_.wait(lock, [this] { return stage_ != Stage::copying; });
  }
  if (failed_) std::rethrow_exception(failed_);
  return *out_;
}

void BackgroundCopy::close() {
  dataset();
  advance(Stage::closing);
  thread_.join();
  if (failed_) std::rethrow_exception(failed_);
}

}  // namespace mcmd::cli
