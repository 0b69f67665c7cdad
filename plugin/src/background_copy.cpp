#include "background_copy.hpp"

#include <utility>

#include "cli_errors.hpp"
#include "errors.hpp"

namespace mcmd::cli {

BackgroundCopy::BackgroundCopy(GDALDriver* driver, std::string source_path, std::string path, CPLStringList co,
                               std::string shown, std::function<bool()> keep_going)
    : driver_(driver),
      source_path_(std::move(source_path)),
      path_(std::move(path)),
      shown_(std::move(shown)),
      co_(std::move(co)),
      keep_going_(std::move(keep_going)),
      thread_(&BackgroundCopy::run, this) {}

BackgroundCopy::~BackgroundCopy() {
  stop_ = true;
  join();
}

void BackgroundCopy::join() {
  if (thread_.joinable()) thread_.join();
}

void BackgroundCopy::run() {
  ErrorLog log;  // this thread's GDAL errors, quietly (the handler stack is per thread)
  const auto fail = [&](const std::string& what) {
    error_ = "cannot write '" + shown_ + "': " + (log.first_failure().empty() ? what : log.first_failure());
  };
  DatasetPtr src(GDALDataset::Open(source_path_.c_str(), GDAL_OF_RASTER | GDAL_OF_READONLY));
  if (!src) return fail("cannot reopen the source");
  const auto progress = [](double, const char*, void* self) -> int {
    auto* copy = static_cast<BackgroundCopy*>(self);
    return !copy->stop_ && copy->keep_going_();
  };
  DatasetPtr out(driver_->CreateCopy(path_.c_str(), src.get(), FALSE, co_.List(), progress, this));
  if (!out) {
    if (CPLGetLastErrorNo() == CPLE_UserInterrupt) {
      cancelled_ = true;
      return;
    }
    return fail(CPLGetLastErrorMsg());
  }
  out.reset();  // flush, then reopen for update
  out.reset(GDALDataset::Open(path_.c_str(), GDAL_OF_RASTER | GDAL_OF_UPDATE));
  if (!out || log.failures() != 0) return fail("cannot reopen it for filling");
  for (int b = 1; b <= src->GetRasterCount(); ++b) copy_band_info(*src->GetRasterBand(b), *out->GetRasterBand(b));
  out_ = std::move(out);
}

GDALDataset& BackgroundCopy::dataset() {
  join();
  if (cancelled_) throw gdal::Failure(CPLE_UserInterrupt, "cancelled by the user");
  if (!out_) throw gdal::Failure(CPLE_FileIO, error_.empty() ? "cannot write '" + shown_ + "'" : error_);
  return *out_;
}

void BackgroundCopy::close() {
  dataset();
  out_.reset();
}

}  // namespace mcmd::cli
