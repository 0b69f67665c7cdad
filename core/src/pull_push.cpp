#include "mcmd/pull_push.hpp"

#include <algorithm>
#include <cstddef>

namespace mcmd {

namespace {

// Coarse level from a fine one given by accessors weight(i) and mean(i).
template <class Weight, class Mean>
PullLevel restrict_level(int fine_w, int fine_h, Weight weight, Mean mean) {
  PullLevel c;
  c.w = coarser_extent(fine_w);
  c.h = coarser_extent(fine_h);
  const std::size_t cells = static_cast<std::size_t>(c.w) * c.h;
  c.mean.assign(cells, 0.0);
  c.weight.assign(cells, 0.0);
  static constexpr double k[3] = {0.5, 1.0, 0.5};
  for (int j = 0; j < c.h; ++j)
    for (int i = 0; i < c.w; ++i) {
      double sw = 0.0, sm = 0.0, sk = 0.0;
      for (int dy = -1; dy <= 1; ++dy) {
        const int y = 2 * j + dy;
        if (y < 0 || y >= fine_h) continue;
        for (int dx = -1; dx <= 1; ++dx) {
          const int x = 2 * i + dx;
          if (x < 0 || x >= fine_w) continue;
          const std::size_t fi = static_cast<std::size_t>(y) * fine_w + x;
          sk += k[dx + 1] * k[dy + 1];
          const double w = k[dx + 1] * k[dy + 1] * weight(fi);
          if (w == 0.0) continue;
          sw += w;
          sm += w * mean(fi);
        }
      }
      const std::size_t ci = static_cast<std::size_t>(j) * c.w + i;
      if (sw > 0) c.mean[ci] = sm / sw;
      if (sk > 0) c.weight[ci] = sw / sk;
    }
  return c;
}

}  // namespace

std::vector<PullLevel> pull(const Lattice& finest) {
  std::vector<PullLevel> levels;
  if (finest.w <= 2 && finest.h <= 2) return levels;
  levels.push_back(restrict_level(
      finest.w, finest.h, [&](std::size_t i) { return finest.pinned[i] ? 1.0 : 0.0; },
      [&](std::size_t i) { return finest.z[i]; }));
  while (levels.back().w > 2 || levels.back().h > 2) {
    const PullLevel& f = levels.back();
    PullLevel c = restrict_level(
        f.w, f.h, [&](std::size_t i) { return f.weight[i]; }, [&](std::size_t i) { return f.mean[i]; });
    levels.push_back(std::move(c));
  }
  std::reverse(levels.begin(), levels.end());
  return levels;
}

}  // namespace mcmd
