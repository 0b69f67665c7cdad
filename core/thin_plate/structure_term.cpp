#include "thin_plate/structure_term.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>

#include "common/box_mean.hpp"

namespace mcmd {

StructureTerm::StructureTerm(const Lattice& lat, double strength, int threads) : w_(lat.w), h_(lat.h) {
  if (!(strength > 1.0) || w_ < 5 || h_ < 5) return;
  blocks_w_ = (w_ + kBlock - 1) / kBlock;
  const int blocks_h = (h_ + kBlock - 1) / kBlock;
  const std::size_t blocks = static_cast<std::size_t>(blocks_w_) * blocks_h;
  // H² = [[a, b], [b, c]] summed per block, from second differences at a
  // spacing of 2 (the cell-scale ones only see the samples' dimples). Each
  // block row sums its own rows in order: the same bits for any thread count.
  std::vector<double> a(blocks, 0.0), b(blocks, 0.0), c(blocks, 0.0);
  const double* z = lat.z.data();
  const int w = w_;
  const std::ptrdiff_t block_rows = blocks_h;
  threads = team(lat, threads);
#pragma omp parallel for num_threads(threads) schedule(static) if (threads > 1)
  for (std::ptrdiff_t by = 0; by < block_rows; ++by) {
    const std::size_t row = static_cast<std::size_t>(by) * blocks_w_;
    const int y_end = std::min(h_ - 2, static_cast<int>(by + 1) * kBlock);
    for (int y = std::max(2, static_cast<int>(by) * kBlock); y < y_end; ++y)
      for (int x = 2; x < w - 2; ++x) {
        const std::size_t i = static_cast<std::size_t>(y) * w + x;
        const double hxx = z[i - 2] - 2 * z[i] + z[i + 2];
        const double hyy = z[i - 2 * w] - 2 * z[i] + z[i + 2 * w];
        const double hxy = z[i + w + 1] - z[i + w - 1] - z[i - w + 1] + z[i - w - 1];
        const std::size_t j = row + static_cast<std::size_t>(x / kBlock);
        a[j] += hxx * hxx + hxy * hxy;
        b[j] += hxy * (hxx + hyy);
        c[j] += hyy * hyy + hxy * hxy;
      }
  }
  // Two 3×3 box means over the blocks: a valley's direction is read over ~12
  // cells, wider than the gaps between scattered samples.
  for (int pass = 0; pass < 2; ++pass)
    for (std::vector<double>* t : {&a, &b, &c}) box_mean(*t, blocks_w_, blocks_h, 1);
  coef_.assign(blocks, Weights{});
  for (std::size_t j = 0; j < blocks; ++j) {
    const double d = a[j] - c[j], trace = a[j] + c[j];
    const double q = std::sqrt(0.25 * d * d + b[j] * b[j]);  // half the eigenvalue gap
    if (!(q > 0) || !(trace > 0)) continue;                  // flat or isotropic: no direction
    // u = (−sin θ, cos θ) with θ the major direction (cos 2θ = d / 2q,
    // sin 2θ = b / q): z_uu = sin²θ z_xx + cos²θ z_yy − sin 2θ z_xy.
    const double coherence = 2 * q / trace, cos2 = 0.5 * d / q, sin2 = b[j] / q;
    const double root_k = std::sqrt((strength - 1.0) * coherence);
    coef_[j] = Weights{root_k * 0.5 * (1 - cos2), root_k * 0.5 * (1 + cos2), -root_k * 0.25 * sin2};
  }
  g_.assign(lat.z.size(), 0.0);
}

void StructureTerm::subtract(const Lattice& lat, const std::vector<double>& v, std::vector<double>& out,
                             int threads) const {
  if (empty()) return;
  const int w = w_, h = h_;
  const double* V = v.data();
  double* g = g_.data();  // 0 on the lattice's edge rows and columns (never written)
  threads = team(lat, threads);
  const std::ptrdiff_t rows = h - 2;
#pragma omp parallel for num_threads(threads) schedule(static) if (threads > 1)
  for (std::ptrdiff_t r = 0; r < rows; ++r) {
    const int y = static_cast<int>(r) + 1;
    const Weights* block_row = row_of(y);
    for (int x = 1; x < w - 1; ++x) {
      const std::size_t i = static_cast<std::size_t>(y) * w + x;
      const Weights& c = block_row[x / kBlock];
      g[i] = c.xx * (V[i - 1] - 2 * V[i] + V[i + 1]) + c.yy * (V[i - w] - 2 * V[i] + V[i + w]) +
             c.xy * (V[i + w + 1] - V[i + w - 1] - V[i - w + 1] + V[i - w - 1]);
    }
  }
  // The transpose: each g_i goes back to the cells of its stencil, times its
  // own block's weight. g is 0 on the edge rows and columns, so only cells
  // on the edge itself need their neighbours checked.
  const std::ptrdiff_t spans = static_cast<std::ptrdiff_t>(lat.spans.size());
#pragma omp parallel for num_threads(threads) schedule(static) if (threads > 1)
  for (std::ptrdiff_t k = 0; k < spans; ++k) {
    const Span& sp = lat.spans[static_cast<std::size_t>(k)];
    const int y = sp.y;
    if (y == 0 || y == h - 1) {
      for (int x = sp.x0; x < sp.x1; ++x) out[lat.index(x, y)] -= transposed_at_edge(x, y);
      continue;
    }
    const Weights *up = row_of(y - 1), *mid = row_of(y), *down = row_of(y + 1);
    const int x0 = std::max(sp.x0, 1), x1 = std::min(sp.x1, w - 1);
    for (int x = sp.x0; x < x0; ++x) out[lat.index(x, y)] -= transposed_at_edge(x, y);
    for (int x = x0; x < x1; ++x) {
      const std::size_t i = lat.index(x, y);
      const int l = (x - 1) / kBlock, c = x / kBlock, r = (x + 1) / kBlock;
      out[i] -= mid[l].xx * g[i - 1] - 2 * mid[c].xx * g[i] + mid[r].xx * g[i + 1] + up[c].yy * g[i - w] -
                2 * mid[c].yy * g[i] + down[c].yy * g[i + w] + up[l].xy * g[i - w - 1] + down[r].xy * g[i + w + 1] -
                up[r].xy * g[i - w + 1] - down[l].xy * g[i + w - 1];
    }
    for (int x = x1; x < sp.x1; ++x) out[lat.index(x, y)] -= transposed_at_edge(x, y);
  }
}

double StructureTerm::transposed_at_edge(int x, int y) const {
  const auto gw = [&](int cx, int cy, double Weights::*part) {
    if (cx < 1 || cy < 1 || cx > w_ - 2 || cy > h_ - 2) return 0.0;
    return at(cx, cy).*part * g_[static_cast<std::size_t>(cy) * w_ + cx];
  };
  return gw(x - 1, y, &Weights::xx) - 2 * gw(x, y, &Weights::xx) + gw(x + 1, y, &Weights::xx) +
         gw(x, y - 1, &Weights::yy) - 2 * gw(x, y, &Weights::yy) + gw(x, y + 1, &Weights::yy) +
         gw(x - 1, y - 1, &Weights::xy) + gw(x + 1, y + 1, &Weights::xy) - gw(x + 1, y - 1, &Weights::xy) -
         gw(x - 1, y + 1, &Weights::xy);
}

}  // namespace mcmd
