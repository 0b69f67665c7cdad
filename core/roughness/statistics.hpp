// Terrain statistics from the constraint cells (internal to roughness/):
// pair sums per block at the lags of the 5-point Laplacian and of the
// semivariogram, the field's semivariogram, and the model (H, curvature).
#pragma once

#include <algorithm>
#include <vector>

#include "common/grid.hpp"
#include "roughness/blocks.hpp"
#include "roughness/field.hpp"

namespace mcmd {

// Terrain statistics from the constraint cells: semivariogram γ(d) over
// horizontal and vertical pairs of constraint cells at lags 1, 2, 4, 8, 16.
struct RoughnessModel {
  double H = 0.5;         // Hurst exponent, from the slope of log γ against log d
  double curvature = 0.0; // variance of a second difference: 8γ(1) - 2γ(2) from many lag-1
                          // pairs, a calibrated fBm form γ(1)(8 - 2·4^H) from few (scattered samples)
  bool valid = false;     // enough pairs to estimate
};
RoughnessModel estimate_roughness(const Grid& grid);
RoughnessModel estimate_roughness(const RoughField& field);


}  // namespace mcmd

namespace mcmd::rough {

inline double smoothstep(double t) {
  t = std::clamp(t, 0.0, 1.0);
  return t * t * (3.0 - 2.0 * t);
}

// Lags (dx, dy) of the pairs of constraint cells summed per block (the
// pair's first cell in the block). The first kLaplacianLags give the variance
// of the 5-point Laplacian of a field with stationary increments,
// 16(γx1+γy1) - 2(γx2+γy2) - 4(γ(1,1)+γ(1,-1)); the x and y pairs at 1, 2, 4,
// 8, 16 give the semivariogram from which H is fitted.
constexpr int kLags = 12;
constexpr int kLaplacianLags = 6;
constexpr int kLagDx[kLags] = {1, 0, 2, 0, 1, 1, 4, 0, 8, 0, 16, 0};
constexpr int kLagDy[kLags] = {0, 1, 0, 2, 1, -1, 0, 4, 0, 8, 0, 16};
// The long lags (4, 8, 16) only feed the field-wide semivariogram (H): their
// pairs are taken on every kLongLagRowStep-th raster row (a quarter of them;
// model_of uses a lag from 30 pairs).
constexpr int kLongLagRowStep = 4;
constexpr int kVariogramLags = 5;  // distances 1, 2, 4, 8, 16: lags kVariogramPair[k]
constexpr int kVariogramPair[kVariogramLags][2] = {{0, 1}, {2, 3}, {6, 7}, {8, 9}, {10, 11}};
// Pairs per lag before a neighbourhood's estimate is trusted: the Laplacian
// variance is a small difference of large γ terms (about 10× cancellation).
constexpr double kMinPairs = 2000;
// Neighbourhoods grow to at most this many blocks around a void block; short
// of kMinPairs there, the estimate blends into the global calibration.
constexpr int kMaxRadius = 4;

struct LagSums {
  double sum[kLags] = {};
  double count[kLags] = {};
  void add(const LagSums& o, double sign = 1.0) {
    for (int l = 0; l < kLags; ++l) {
      sum[l] += sign * o.sum[l];
      count[l] += sign * o.count[l];
    }
  }
  double gamma(int l) const { return count[l] > 0 ? 0.5 * sum[l] / count[l] : 0.0; }
  double min_laplacian_count() const { return *std::min_element(count, count + kLaplacianLags); }
  double laplacian_variance() const {
    return 16.0 * (gamma(0) + gamma(1)) - 2.0 * (gamma(2) + gamma(3)) - 4.0 * (gamma(4) + gamma(5));
  }
};

// Per block, the pair sums of every lag; block rows on `threads` threads, each
// block summed by one thread in a fixed order (the same bits for any count).
std::vector<LagSums> pair_sums(const RoughField& g, const Blocks& b, int threads);

// The semivariogram γ(d) over the whole field, d = 1, 2, 4, 8, 16.
struct Variogram {
  double gamma[kVariogramLags] = {};
  double pairs[kVariogramLags] = {};
};
Variogram variogram_of(const std::vector<LagSums>& blocks);

// Summed-area table of the per-block lag sums: any square neighbourhood in O(1).
class LagTable {
 public:
  LagTable(const std::vector<LagSums>& block, const Blocks& b)
      : nx_(b.nx), ny_(b.ny), sat_(static_cast<std::size_t>(b.nx + 1) * (b.ny + 1)) {
    for (int j = 0; j < ny_; ++j)
      for (int i = 0; i < nx_; ++i) {
        LagSums& s = sat_[at(i + 1, j + 1)];
        s = block[b.index(i, j)];
        s.add(sat_[at(i, j + 1)]);
        s.add(sat_[at(i + 1, j)]);
        s.add(sat_[at(i, j)], -1.0);
      }
  }
  // Sums over blocks [i0, i1] × [j0, j1], clipped to the lattice.
  LagSums box(int i0, int j0, int i1, int j1) const {
    i0 = std::max(i0, 0); j0 = std::max(j0, 0);
    i1 = std::min(i1, nx_ - 1); j1 = std::min(j1, ny_ - 1);
    LagSums s = sat_[at(i1 + 1, j1 + 1)];
    s.add(sat_[at(i0, j1 + 1)], -1.0);
    s.add(sat_[at(i1 + 1, j0)], -1.0);
    s.add(sat_[at(i0, j0)]);
    return s;
  }

 private:
  std::size_t at(int i, int j) const { return static_cast<std::size_t>(j) * (nx_ + 1) + i; }
  int nx_, ny_;
  std::vector<LagSums> sat_;
};


// H and the field's curvature from its semivariogram.
RoughnessModel model_of(const Variogram& vg);

}  // namespace mcmd::rough
