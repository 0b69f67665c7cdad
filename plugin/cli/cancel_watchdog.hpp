// A run told to stop (SIGINT, SIGTERM) stops at its next progress report,
// but some of GDAL's steps report none: closing an uncompressed GeoTIFF
// writes every block nobody wrote (a sparse source's: 3.2 GB, 10 s after the
// signal for a 40000² VRT over a small file). The watchdog gives a run that
// writes a copy 0.3 s after the signal; if it has not ended by then
// the watchdog ends it: the copy's temporary folder removed, the error line
// printed, exit 1. In place it waits for the run (a write stopped half-way
// could damage the source).
#pragma once

#include <atomic>
#include <condition_variable>
#include <functional>
#include <mutex>
#include <thread>

namespace mcmd::cli {

class CancelWatchdog {
 public:
  // `say_cancelled` prints the error line (from the watchdog's thread).
  explicit CancelWatchdog(std::function<void()> say_cancelled);
  CancelWatchdog(const CancelWatchdog&) = delete;
  CancelWatchdog& operator=(const CancelWatchdog&) = delete;
  ~CancelWatchdog();

  // The run's end, before main prints its last line: false when the
  // watchdog has taken over (main must then print nothing: it is ended).
  bool claim_exit();

 private:
  void watch();
  std::function<void()> say_cancelled_;
  std::atomic<bool> claimed_{false};
  bool done_ = false;
  std::mutex mutex_;
  std::condition_variable changed_;
  std::thread thread_;
};

}  // namespace mcmd::cli
