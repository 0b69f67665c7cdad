#include "mcmd/progress.hpp"

#include <algorithm>

namespace mcmd {

void report(const ProgressFn& fn, double fraction, double lo, double hi) {
  if (!fn) return;
  const double f = lo + (hi - lo) * std::clamp(fraction, 0.0, 1.0);
  if (!fn(f)) throw Cancelled();
}

ProgressFn sub_progress(const ProgressFn& parent, double lo, double hi) {
  if (!parent) return {};
  return [parent, lo, hi](double f) { return parent(lo + (hi - lo) * std::clamp(f, 0.0, 1.0)); };
}

}  // namespace mcmd
