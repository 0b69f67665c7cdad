#include "terrain/erosion/hillslope.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace mcmd::terrain {

namespace {

// `count` lines of `n` cells, line l's cell i at l·line_step + i·cell_step.
struct Lines {
  std::ptrdiff_t line_step, cell_step;
  int count, n;
};

// Lines solved together, cell by cell, so that a column solve reads rows of
// contiguous cells.
constexpr int kBlock = 16;

// (1 + 2k) z_i − k (z_{i−1} + z_{i+1}) = z_i at free interior cells, z_i
// kept at fixed ones and the ends (Thomas' algorithm) for lines
// first .. first + lines − 1.
void solve_block(double* z, const std::uint8_t* fixed, const Lines& L, int first, int lines, double k,
                 std::vector<double>& cp, std::vector<double>& dp) {
  cp.resize(static_cast<std::size_t>(L.n) * kBlock);
  dp.resize(static_cast<std::size_t>(L.n) * kBlock);
  for (int i = 0; i < L.n; ++i)
    for (int l = 0; l < lines; ++l) {
      const std::ptrdiff_t at = (first + l) * L.line_step + i * L.cell_step;
      const std::size_t s = static_cast<std::size_t>(i) * kBlock + l;
      const bool free = !fixed[at] && i > 0 && i < L.n - 1;
      const double a = free ? -k : 0.0, b = free ? 1.0 + 2.0 * k : 1.0, c = free ? -k : 0.0;
      const double cprev = i > 0 ? cp[s - kBlock] : 0.0, dprev = i > 0 ? dp[s - kBlock] : 0.0;
      const double m = b - a * cprev;
      cp[s] = c / m;
      dp[s] = (z[at] - a * dprev) / m;
    }
  for (int i = L.n - 1; i >= 0; --i)
    for (int l = 0; l < lines; ++l) {
      const std::ptrdiff_t at = (first + l) * L.line_step + i * L.cell_step;
      const std::size_t s = static_cast<std::size_t>(i) * kBlock + l;
      z[at] = dp[s] - cp[s] * (i < L.n - 1 ? z[at + L.cell_step] : 0.0);
    }
}

void solve_lines(double* z, const std::uint8_t* fixed, const Lines& L, double k, int threads) {
  const int blocks = (L.count + kBlock - 1) / kBlock;
#pragma omp parallel num_threads(threads) if (threads > 1)
  {
    std::vector<double> cp, dp;
#pragma omp for schedule(static)
    for (int b = 0; b < blocks; ++b)
      solve_block(z, fixed, L, b * kBlock, std::min(kBlock, L.count - b * kBlock), k, cp, dp);
  }
}

}  // namespace

void diffuse(std::vector<double>& z, const std::vector<std::uint8_t>& fixed, int w, int h, double d_dt, int threads) {
  if (d_dt <= 0.0 || w < 3 || h < 3) return;
  solve_lines(z.data(), fixed.data(), Lines{w, 1, h, w}, d_dt, threads);  // along the rows
  solve_lines(z.data(), fixed.data(), Lines{1, w, w, h}, d_dt, threads);  // along the columns
}

void limit_slopes(std::vector<double>& z, const std::vector<std::uint8_t>& fixed, int w, int h, double slope) {
  const double diagonal = slope * M_SQRT2;
  const auto limit = [&](int x, int y) {
    const std::size_t i = static_cast<std::size_t>(y) * w + x;
    if (fixed[i]) return;
    double v = z[i];
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) {
        const int nx = x + dx, ny = y + dy;
        if ((dx == 0 && dy == 0) || nx < 0 || ny < 0 || nx >= w || ny >= h) continue;
        v = std::min(v, z[static_cast<std::size_t>(ny) * w + nx] + (dx && dy ? diagonal : slope));
      }
    z[i] = v;
  };
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) limit(x, y);
  for (int y = h - 1; y >= 0; --y)
    for (int x = w - 1; x >= 0; --x) limit(x, y);
}

}  // namespace mcmd::terrain
