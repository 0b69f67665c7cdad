#include "common/padding.hpp"

#include <algorithm>

namespace mcmd {

int reflect_out_of_range(long long i, int len) {
  if (len <= 1) return 0;
  const long long period = 2LL * (len - 1);
  long long m = i % period;
  if (m < 0) m += period;
  return static_cast<int>(m < len ? m : period - m);
}

int levels_to_cover(int w, int h) {
  const int need = std::max(w, h);
  int n = 0;
  while ((1 << n) + 1 < need) ++n;
  return n;
}

Grid mirror_padded_grid(const double* z, const std::uint8_t* valid, int w, int h, int n, int x0, int y0) {
  Grid g(n);
  for (int y = 0; y < g.side(); ++y) {
    const std::size_t row =
        static_cast<std::size_t>(reflect_index(static_cast<long long>(y0) + y, h)) * static_cast<std::size_t>(w);
    for (int x = 0; x < g.side(); ++x) {
      const std::size_t src = row + static_cast<std::size_t>(reflect_index(static_cast<long long>(x0) + x, w));
      if (!valid[src]) continue;
      g.z(x, y) = z[src];
      g.state(x, y) = CellState::known;
    }
  }
  return g;
}

}  // namespace mcmd
