#include <algorithm>
#include <stdexcept>

#include "mcmd/terrain_filters.hpp"

namespace mcmd {

namespace {

// One pass from `from` into `to` (rows in parallel: each cell is one
// nth_element of its own window, the same for any thread count).
void median_pass(const Canvas& c, const std::vector<double>& from, std::vector<double>& to, int r, bool all,
                 int threads) {
#pragma omp parallel for num_threads(threads) schedule(static) if (threads > 1)
  for (int y = 0; y < c.h; ++y) {
    std::vector<double> window;
    for (int x = 0; x < c.w; ++x) {
      const std::size_t i = c.index(x, y);
      if (!all && is_constraint(c.state[i])) {
        to[i] = from[i];
        continue;
      }
      window.clear();
      for (int v = std::max(0, y - r); v <= std::min(c.h - 1, y + r); ++v)
        for (int u = std::max(0, x - r); u <= std::min(c.w - 1, x + r); ++u) window.push_back(from[c.index(u, v)]);
      const auto mid = window.begin() + static_cast<std::ptrdiff_t>(window.size() / 2);
      std::nth_element(window.begin(), mid, window.end());
      to[i] = *mid;
    }
  }
}

}  // namespace

void median_filter(Canvas& c, int size, int passes, bool all_cells, int threads) {
  if (size < 3 || size % 2 == 0 || size > 101) throw std::invalid_argument("the median size must be odd, in [3, 101]");
  if (passes < 1 || passes > 100) throw std::invalid_argument("the median passes must be in [1, 100]");
  std::vector<double> other(c.cells());
  for (int p = 0; p < passes; ++p) {
    median_pass(c, c.z, other, size / 2, all_cells, threads);
    c.z.swap(other);
  }
}

}  // namespace mcmd
