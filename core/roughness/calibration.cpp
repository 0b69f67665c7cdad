#include "roughness/calibration.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "roughness/simd.hpp"

namespace mcmd::rough {

namespace {

// Laplacian variance ÷ twice the second-difference variance on the benchmark
// DEMs (dense data): 1.37-1.47, median 1.39 (dxx and dyy correlate).
constexpr double kLapPerCurvature = 1.39;

}  // namespace

std::vector<NoiseMoments> noise_moments(const RoughField& g, const Area& a, const std::vector<std::uint8_t>& target,
                                        const Blocks& b, const std::vector<double>& noise, int threads) {
  std::vector<NoiseMoments> out(static_cast<std::size_t>(b.nx) * b.ny);
  const int w = a.w;
#pragma omp parallel for num_threads(threads) schedule(dynamic) if (threads > 1)
  for (int bj = 0; bj < b.ny; ++bj)
    for (int bi = 0; bi < b.nx; ++bi) {
      if (!b.active(bi, bj)) continue;
      const int x0 = std::max(1, b.x0(bi)), n_x = std::min(b.x1(bi, g.w), g.w - 1) - x0;
      NoiseMoments m;
      for (int y = std::max(1, b.y0(bj)); y < std::min(b.y1(bj, g.h), g.h - 1); ++y) {
        if ((g.y0 + y) & 2) continue;  // raster rows 0 and 1 mod 4 only (bits: also below 0)
        const double* v = noise.data() + a.index(x0, y);
        const std::uint8_t* t = target.data() + a.index(x0, y);
        if (!std::memchr(t, 1, static_cast<std::size_t>(std::max(0, n_x)))) continue;  // adds 0: a small void's rows
        double n = 0, q = 0, qq = 0, cv = 0;
#pragma omp simd reduction(+ : n, q, qq, cv)
        for (int k = 0; k < n_x; ++k) {
          const double weight = t[k];  // 0 or 1: arithmetic, not a select, so that it vectorises
          const double dxx = v[k - 1] - 2.0 * v[k] + v[k + 1], dyy = v[k - w] - 2.0 * v[k] + v[k + w];
          const double lq = dxx + dyy;
          n += weight;
          q += weight * lq;
          qq += weight * (lq * lq);
          cv += weight * (dxx * dxx + dyy * dyy);
        }
        m.add(NoiseMoments{n, q, qq, cv});
      }
      out[b.index(bi, bj)] = m;
    }
  return out;
}


std::vector<double> block_scales(const Blocks& blocks, const LagTable& lags, const std::vector<NoiseMoments>& lap,
                                 const RoughnessModel& global, double global_scale) {
  const int nbx = blocks.nx, nby = blocks.ny;
  const double global_target = kLapPerCurvature * 2.0 * global.curvature;
  std::vector<double> scale(static_cast<std::size_t>(nbx) * nby, -1.0);
  for (int bj = 0; bj < nby; ++bj)
    for (int bi = 0; bi < nbx; ++bi) {
      if (lap[blocks.index(bi, bj)].n == 0) continue;
      LagSums around;
      for (int r = 1; r <= kMaxRadius; ++r) {
        around = lags.box(bi - r, bj - r, bi + r, bj + r);
        if (around.min_laplacian_count() >= kMinPairs) break;
      }
      const double local = around.laplacian_variance();
      const double trust =
          local > 0 ? smoothstep((around.min_laplacian_count() - 0.25 * kMinPairs) / (0.75 * kMinPairs)) : 0.0;
      const double target = trust * local + (1.0 - trust) * global_target;
      NoiseMoments m;
      for (int dj = -1; dj <= 1; ++dj)
        for (int di = -1; di <= 1; ++di)
          if (blocks.inside(bi + di, bj + dj)) m.add(lap[blocks.index(bi + di, bj + dj)]);
      const double vq = m.laplacian_var();
      scale[blocks.index(bi, bj)] = vq > 0 ? std::sqrt(target / vq) : global_scale;
    }
  std::vector<double> filled = scale;
  for (int bj = 0; bj < nby; ++bj)
    for (int bi = 0; bi < nbx; ++bi) {
      if (scale[blocks.index(bi, bj)] >= 0) continue;
      double s = 0, n = 0;
      for (int dj = -1; dj <= 1; ++dj)
        for (int di = -1; di <= 1; ++di) {
          if (!blocks.inside(bi + di, bj + dj)) continue;
          const double v = scale[blocks.index(bi + di, bj + dj)];
          if (v >= 0) { s += v; n += 1; }
        }
      filled[blocks.index(bi, bj)] = n > 0 ? s / n : global_scale;
    }
  return filled;
}

// noise (over area `a`) × the block scales interpolated bilinearly between
// block centres (a smooth amplitude field), in place; the noise lies in the
// active blocks' noise boxes only.
void scale_noise(const Area& a, const Blocks& blocks, const std::vector<double>& scales, std::vector<double>& noise,
                 int threads) {
  // A scale that is not finite (no noise there to measure) counts as 0, so
  // that v · f is 0 where v is: no test per cell, and the loop vectorises.
  const auto at = [&](int bi, int bj) {
    const double s = scales[blocks.index(std::clamp(bi, 0, blocks.nx - 1), std::clamp(bj, 0, blocks.ny - 1))];
    return std::isfinite(s) ? s : 0.0;
  };
#pragma omp parallel for num_threads(threads) schedule(dynamic) if (threads > 1)
  for (int bj = 0; bj < blocks.ny; ++bj)
    for (int bi = 0; bi < blocks.nx; ++bi) {
      if (!blocks.active(bi, bj)) continue;
      const Rect& r = blocks.noise_box[blocks.index(bi, bj)];
      for (int y = r.y0; y < r.y1; ++y) {
        const double fy = (y + blocks.oy + 0.5) / kBlock - 0.5;
        const int cj = static_cast<int>(floor_of(fy));
        const double ty = fy - cj;
        double* row = noise.data() + a.index(a.x0, y);  // row[x - a.x0]: cell x
        // The row in runs of one pair of block centres (ci, ci + 1): the
        // left and the right half of the block.
        for (int x0 = r.x0; x0 < r.x1;) {
          const int ci = static_cast<int>(floor_of((x0 + blocks.ox + 0.5) / kBlock - 0.5));
          const int x1 = std::min(r.x1, (ci + 1) * kBlock + kBlock / 2 - blocks.ox);  // the next centre
          const double s00 = at(ci, cj), s10 = at(ci + 1, cj), s01 = at(ci, cj + 1), s11 = at(ci + 1, cj + 1);
          // Bilinear, linear in tx along the run: f = left + tx · slope.
          const double left = (1 - ty) * s00 + ty * s01, slope = (1 - ty) * (s10 - s00) + ty * (s11 - s01);
          for (int x = x0; x < x1; ++x) {
            const double tx = (x + blocks.ox + 0.5) / kBlock - 0.5 - ci;
            row[x - a.x0] *= left + tx * slope;  // f >= 0: +0.0 where there is no noise stays +0.0
          }
          x0 = x1;
        }
      }
    }
}


}  // namespace mcmd::rough
