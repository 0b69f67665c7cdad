#include "common/box_mean.hpp"

#include <algorithm>
#include <cstddef>

namespace mcmd {

void box_mean_pass(std::vector<double>& v, int w, int h, int r, bool rows) {
  const int n = rows ? w : h, lines = rows ? h : w;
  const std::size_t step = rows ? 1 : static_cast<std::size_t>(w);
  std::vector<double> line(static_cast<std::size_t>(n)), prefix(static_cast<std::size_t>(n) + 1);
  for (int l = 0; l < lines; ++l) {
    const std::size_t base = rows ? static_cast<std::size_t>(l) * w : static_cast<std::size_t>(l);
    prefix[0] = 0.0;
    for (int k = 0; k < n; ++k) prefix[k + 1] = prefix[k] + v[base + k * step];
    for (int k = 0; k < n; ++k) {
      const int a = std::max(0, k - r), b = std::min(n, k + r + 1);
      line[k] = (prefix[b] - prefix[a]) / (b - a);
    }
    for (int k = 0; k < n; ++k) v[base + k * step] = line[k];
  }
}

}  // namespace mcmd
