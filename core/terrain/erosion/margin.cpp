#include "terrain/erosion/margin.hpp"

#include <algorithm>
#include <cstddef>

namespace mcmd::terrain {

namespace {

constexpr int kMargin = 32;

int mirrored(int v, int n) {
  if (v < 0) v = -v;
  if (v >= n) v = 2 * (n - 1) - v;
  return v;
}

}  // namespace

int margin_of(int w, int h) { return std::min(kMargin, std::min(w, h) / 4); }

std::vector<double> with_margin(const std::vector<double>& f, int w, int h, int m) {
  const int bw = w + 2 * m, bh = h + 2 * m;
  std::vector<double> out(static_cast<std::size_t>(bw) * bh);
  for (int y = 0; y < bh; ++y)
    for (int x = 0; x < bw; ++x)
      out[static_cast<std::size_t>(y) * bw + x] = f[static_cast<std::size_t>(mirrored(y - m, h)) * w + mirrored(x - m, w)];
  return out;
}

Canvas with_margin(const Canvas& c, int m) {
  Canvas big(c.w + 2 * m, c.h + 2 * m);
  big.z = with_margin(c.z, c.w, c.h, m);
  for (int y = 0; y < c.h; ++y)
    for (int x = 0; x < c.w; ++x) big.state[big.index(x + m, y + m)] = c.state[c.index(x, y)];
  return big;
}

void without_margin(const Canvas& big, int m, Canvas& c) {
  for (int y = 0; y < c.h; ++y)
    for (int x = 0; x < c.w; ++x) c.z[c.index(x, y)] = big.z[big.index(x + m, y + m)];
}

}  // namespace mcmd::terrain
