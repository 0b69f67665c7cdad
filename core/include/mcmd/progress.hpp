// Progress reporting and cancellation shared by every long-running core pass.
#pragma once

#include <functional>
#include <stdexcept>

namespace mcmd {

// Called with a fraction in [0, 1]; returning false asks the pass to stop.
using ProgressFn = std::function<bool(double fraction)>;

// Thrown by a pass whose progress callback returned false.
class Cancelled : public std::runtime_error {
 public:
  Cancelled() : std::runtime_error("cancelled by the user") {}
};

// Report `fraction` of [lo, hi] to `fn` (if any); throws Cancelled on refusal.
void report(const ProgressFn& fn, double fraction, double lo = 0.0, double hi = 1.0);

// A callback that maps [0, 1] onto [lo, hi] of `parent`.
ProgressFn sub_progress(const ProgressFn& parent, double lo, double hi);

}  // namespace mcmd
