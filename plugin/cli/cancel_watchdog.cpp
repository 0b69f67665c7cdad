#include "cli/cancel_watchdog.hpp"

#include <chrono>
#include <cstdio>
#include <unistd.h>
#include <utility>

#include "cli/output_file.hpp"
#include "cli/run.hpp"

namespace mcmd::cli {

namespace {

constexpr auto kPoll = std::chrono::milliseconds(20);
constexpr auto kGrace = std::chrono::milliseconds(300);

}  // namespace

CancelWatchdog::CancelWatchdog(std::function<void()> say_cancelled)
    : say_cancelled_(std::move(say_cancelled)), thread_(&CancelWatchdog::watch, this) {}

CancelWatchdog::~CancelWatchdog() {
  {
    const std::lock_guard lock(mutex_);
    done_ = true;
  }
  changed_.notify_all();
  thread_.join();
}

bool CancelWatchdog::claim_exit() {
  if (claimed_.exchange(true)) return false;
  {
    const std::lock_guard lock(mutex_);
    done_ = true;
  }
  changed_.notify_all();
  return true;
}

void CancelWatchdog::watch() {
  std::unique_lock lock(mutex_);
  while (!done_) {
    changed_.wait_for(lock, kPoll);
    if (done_ || !interrupted()) continue;
    if (changed_.wait_for(lock, kGrace, [this] { return done_; })) return;
    if (!writing_temporaries()) continue;  // in place: the run ends by itself
    if (claimed_.exchange(true)) return;   // main is ending it
    say_cancelled_();
    remove_active_temporaries();
    std::fflush(nullptr);
    ::_exit(1);
  }
}

}  // namespace mcmd::cli
