// The box mean of a w×h row-major grid: each cell becomes the mean of the
// cells within r of it along rows, then along columns, the window shrinking
// at the borders (no padding, no bias towards 0 at the edges). Repeated
// passes approach a Gaussian.
#pragma once

#include <vector>

namespace mcmd {

// One pass along rows (`rows`) or columns, in place. Pre: v.size() == w·h.
void box_mean_pass(std::vector<double>& v, int w, int h, int r, bool rows);

// A pass along rows, then one along columns.
inline void box_mean(std::vector<double>& v, int w, int h, int r) {
  box_mean_pass(v, w, h, r, true);
  box_mean_pass(v, w, h, r, false);
}

}  // namespace mcmd
