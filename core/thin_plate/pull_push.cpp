#include "thin_plate/pull_push.hpp"

#include <algorithm>
#include <cstddef>

namespace mcmd {

namespace {

constexpr double kTap[3] = {0.5, 1.0, 0.5};  // per axis: the transpose of linear interpolation

// Coarse cell (i, j) from the fine cells around (2i, 2j) that lie inside the
// fine level, given by accessors weight(index) and mean(index); taps of
// weight 0 are skipped. Sets m (left as it is without weight) and wt.
template <class Weight, class Mean>
void restrict_edge_cell(int i, int j, int fine_w, int fine_h, Weight weight, Mean mean, double& m, double& wt) {
  double sw = 0.0, sm = 0.0, sk = 0.0;
  for (int dy = -1; dy <= 1; ++dy) {
    const int y = 2 * j + dy;
    if (y < 0 || y >= fine_h) continue;
    for (int dx = -1; dx <= 1; ++dx) {
      const int x = 2 * i + dx;
      if (x < 0 || x >= fine_w) continue;
      const std::size_t fi = static_cast<std::size_t>(y) * fine_w + x;
      sk += kTap[dx + 1] * kTap[dy + 1];
      const double w = kTap[dx + 1] * kTap[dy + 1] * weight(fi);
      if (w == 0.0) continue;
      sw += w;
      sm += w * mean(fi);
    }
  }
  if (sw > 0) m = sm / sw;
  if (sk > 0) wt = sw / sk;
}

// The same for the coarse cells [i0, i1) of row j whose nine taps all lie
// inside, without a test per tap: a tap of weight 0 adds +0.0, which leaves
// both sums as they were (neither can be -0.0), and the kernel sums to
// exactly 4. Same bits as the edge path, without a branch per tap.
template <class Weight, class Mean>
void restrict_inner_run(int i0, int i1, int j, int fine_w, Weight weight, Mean mean, double* m, double* wt) {
  const std::size_t row = static_cast<std::size_t>(2 * j) * fine_w;
  for (int i = i0; i < i1; ++i) {
    const std::size_t centre = row + 2 * static_cast<std::size_t>(i);
    double sw = 0.0, sm = 0.0;
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) {
        const std::size_t fi = centre + static_cast<std::ptrdiff_t>(dy) * fine_w + dx;
        const double w = kTap[dx + 1] * kTap[dy + 1] * weight(fi);
        sw += w;
        sm += w == 0.0 ? 0.0 : w * mean(fi);
      }
    m[i] = sw > 0 ? sm / sw : m[i];
    wt[i] = sw / 4.0;
  }
}

// Coarse level from a fine one given by accessors weight(i) and mean(i).
template <class Weight, class Mean>
PullLevel restrict_level(int fine_w, int fine_h, Weight weight, Mean mean) {
  PullLevel c;
  c.w = coarser_extent(fine_w);
  c.h = coarser_extent(fine_h);
  const std::size_t cells = static_cast<std::size_t>(c.w) * c.h;
  c.mean.assign(cells, 0.0);
  c.weight.assign(cells, 0.0);
  // Coarse cells in [1, inner_w) x [1, inner_h) have all their taps inside.
  const int inner_w = fine_w / 2, inner_h = fine_h / 2;
  for (int j = 0; j < c.h; ++j) {
    double* m = c.mean.data() + static_cast<std::size_t>(j) * c.w;
    double* wt = c.weight.data() + static_cast<std::size_t>(j) * c.w;
    const bool inner_row = j >= 1 && j < inner_h && inner_w > 1;
    const int edge_from = inner_row ? inner_w : 0;
    if (inner_row) {
      restrict_edge_cell(0, j, fine_w, fine_h, weight, mean, m[0], wt[0]);
      restrict_inner_run(1, inner_w, j, fine_w, weight, mean, m, wt);
    }
    for (int i = edge_from; i < c.w; ++i) restrict_edge_cell(i, j, fine_w, fine_h, weight, mean, m[i], wt[i]);
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
