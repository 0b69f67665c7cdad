#include "roughness/statistics.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "common/zero_runs.hpp"
#include "roughness/simd.hpp"

namespace mcmd::rough {

namespace {

// Second-difference variance of the benchmark DEMs (dense data) ÷ the fBm form
// γ(1)(8 - 2·4^H) with their own γ(1), H: 0.30-0.60, median 0.34.
constexpr double kFbmToTerrain = 0.34;
// Lag-1 pairs from which 8γ(1) - 2γ(2) is trusted fully (from a tenth of it, partly).
constexpr double kDensePairs = 40000;

// One lag's pairs along a row segment of n cells: z is 0 and m 0 at the
// non-constraint cells, m 1 at the constraints. Arithmetic only, four cells at
// a time in Quad accumulators, their lanes added in a fixed order (an omp
// simd reduction kept its partial sums in memory, a store per step).
struct PairRun {
  double sum = 0.0, count = 0.0;
};
[[gnu::always_inline]] inline PairRun pair_run(const double* __restrict z0, const double* __restrict m0,
                                               const double* __restrict z1, const double* __restrict m1, int n) {
  const auto load = [](const double* p) {
    Quad v;
    std::memcpy(&v, p, sizeof v);
    return v;
  };
  Quad sum{}, count{};
  int x = 0;
  for (; x + 3 < n; x += 4) {
    const Quad d = load(z1 + x) - load(z0 + x), m = load(m0 + x) * load(m1 + x);
    sum += m * (d * d);
    count += m;
  }
  PairRun r{(sum[0] + sum[1]) + (sum[2] + sum[3]), (count[0] + count[1]) + (count[2] + count[3])};
  for (; x < n; ++x) {
    const double d = z1[x] - z0[x], m = m0[x] * m1[x];
    r.sum += m * (d * d);
    r.count += m;
  }
  return r;
}

// z = the value at a constraint, +0.0 elsewhere; m = 1.0 or +0.0. As bit masks:
// GCC vectorises the and of a widened byte with the value's bits, not the
// select (scalar: ~12 instructions a cell, a fifth of block_row_pairs' time).
[[gnu::always_inline]] inline void constraint_values(const CellState* __restrict c, const double* __restrict v,
                                                     std::size_t n, double* __restrict z, double* __restrict m) {
  constexpr std::uint64_t kOne = 0x3ff0000000000000;  // the bits of 1.0
  for (std::size_t i = 0; i < n; ++i) {
    const std::uint64_t keep = is_constraint(c[i]) ? ~std::uint64_t{0} : 0;
    std::uint64_t bits;
    std::memcpy(&bits, v + i, sizeof bits);
    bits &= keep;
    std::memcpy(z + i, &bits, sizeof bits);
    const std::uint64_t one = kOne & keep;
    std::memcpy(m + i, &one, sizeof one);
  }
}

// A row with fewer constraints than 1 in kSparseRow of its cells (scattered
// samples: 3.3 % kept) takes its pairs from the list of its constraints, not
// lane by lane over every cell: on a 2100×1100 crop of the 3.3 %-kept mosaic,
// -rs auto's pair sums 138 -> 63 M instructions, the same output. A denser
// row holds pairs enough on every other raster row: only even ones are
// summed (White Mountains blobs, -rs auto: 1.759 -> 1.685 G instructions,
// the smooth fill's 1.475).
constexpr std::size_t kSparseRow = 8;

// The pairs of lag l from row y's constraints `known` (a sparse row), into
// their blocks' sums, read from the field itself (the values pair_run's z
// holds at constraints, bit for bit).
void add_listed_pairs(const RoughField& g, const Blocks& b, int bj, int y, int l, const std::vector<int>& known,
                      std::vector<LagSums>& out) {
  const int dx = kLagDx[l], py = y + kLagDy[l];
  for (const int x : known) {
    if (x + dx >= g.w) break;
    const std::size_t p = g.index(x + dx, py);
    if (!is_constraint(g.state[p])) continue;
    const double d = g.z[p] - g.z[g.index(x, y)];
    LagSums& s = out[b.index((x + b.ox) / kBlock, bj)];
    s.sum[l] += d * d;
    s.count[l] += 1.0;
  }
}

// The pair sums of the blocks of block row bj into `out`. Dense rows run
// pair_run on a copy of the block row's rows and the 16 below as its z and m,
// made only when a row is dense: scattered samples (every row sparse) skip
// that pass over 49 rows per 32 (buffers reused by the caller; `known`: a
// sparse row's constraint columns). Cloned for AVX2 as add_octave is (the
// same bits).
MCMD_AVX2_CLONES
void block_row_pairs(const RoughField& g, const Blocks& b, int bj, std::vector<double>& z, std::vector<double>& m,
                     std::vector<int>& known, std::vector<LagSums>& out) {
  constexpr int kReach = 16;  // the longest lag
  const int y0 = b.y0(bj), y1 = b.y1(bj, g.h);
  if (y1 <= y0) return;
  bool sparse[kBlock];
  bool any_dense = false;
  for (int y = y0; y < y1; ++y) {
    const CellState* row = g.state + g.index(0, y);
    const auto count = static_cast<std::size_t>(std::count_if(row, row + g.w, is_constraint));
    sparse[y - y0] = count * kSparseRow < static_cast<std::size_t>(g.w);
    any_dense |= !sparse[y - y0] && positive_mod(g.y0 + y, 2) == 0;
  }
  // Rows ry0 .. ry1 - 1 (from one above, for the (1, -1) lag).
  const int ry0 = std::max(0, y0 - 1), ry1 = std::min(g.h, y1 + kReach);
  if (any_dense) {
    const std::size_t first = g.index(0, ry0), cells = static_cast<std::size_t>(ry1 - ry0) * g.w;
    z.resize(cells);
    m.resize(cells);
    constraint_values(g.state + first, g.z + first, cells, z.data(), m.data());
  }
  const auto at = [&](int x, int y) { return static_cast<std::size_t>(y - ry0) * g.w + x; };
  for (int y = y0; y < y1; ++y) {
    const CellState* row = g.state + g.index(0, y);
    if (!sparse[y - y0] && positive_mod(g.y0 + y, 2) != 0) continue;
    known.clear();
    if (sparse[y - y0])
      detail::for_each_constraint(row, g.w, [&](int x) { known.push_back(x); });
    for (int l = 0; l < kLags; ++l) {
      const int dx = kLagDx[l], py = y + kLagDy[l];
      if (py < 0 || py >= g.h || dx >= g.w) continue;
      if (l >= kLaplacianLags && positive_mod(g.y0 + y, kLongLagRowStep) != 0) continue;
      if (sparse[y - y0]) {
        add_listed_pairs(g, b, bj, y, l, known, out);
        continue;
      }
      for (int bi = 0; bi < b.nx; ++bi) {
        const int x0 = b.x0(bi), x1 = std::min(b.x1(bi, g.w), g.w - dx);
        if (x1 <= x0) continue;
        const PairRun r = pair_run(&z[at(x0, y)], &m[at(x0, y)], &z[at(x0 + dx, py)], &m[at(x0 + dx, py)], x1 - x0);
        LagSums& s = out[b.index(bi, bj)];
        s.sum[l] += r.sum;
        s.count[l] += r.count;
      }
    }
  }
}

}  // namespace

std::vector<LagSums> pair_sums(const RoughField& g, const Blocks& b,
                               int threads) {
  std::vector<LagSums> out(static_cast<std::size_t>(b.nx) * b.ny);
#pragma omp parallel num_threads(threads) if (threads > 1)
  {
    std::vector<double> z, m;
    std::vector<int> known;
#pragma omp for schedule(dynamic)
    for (int bj = 0; bj < b.ny; ++bj) block_row_pairs(g, b, bj, z, m, known, out);
  }
  return out;
}


Variogram variogram_of(const std::vector<LagSums>& blocks) {
  LagSums total;
  for (const LagSums& s : blocks) total.add(s);
  Variogram v;
  for (int k = 0; k < kVariogramLags; ++k) {
    const int a = kVariogramPair[k][0], b = kVariogramPair[k][1];
    v.pairs[k] = total.count[a] + total.count[b];
    v.gamma[k] = v.pairs[k] > 0 ? 0.5 * (total.sum[a] + total.sum[b]) / v.pairs[k] : 0.0;
  }
  return v;
}


RoughnessModel model_of(const Variogram& vg) {
  RoughnessModel m;
  double sx = 0, sy = 0, sxx = 0, sxy = 0, n = 0, g1 = 0, g2 = 0, pairs1 = 0;
  for (int k = 0, d = 1; k < kVariogramLags; ++k, d *= 2) {
    const double pairs = vg.pairs[k];
    const double gamma = vg.gamma[k];
    if (pairs < 30 || gamma <= 0) continue;
    if (d == 1) { g1 = gamma; pairs1 = pairs; }
    if (d == 2) g2 = gamma;
    const double lx = std::log(static_cast<double>(d)), ly = std::log(gamma);
    sx += lx; sy += ly; sxx += lx * lx; sxy += lx * ly; n += 1;
  }
  if (n < 2 || g1 <= 0) return m;
  const double slope = (n * sxy - sx * sy) / (n * sxx - sx * sx);  // 2H
  m.H = std::clamp(0.5 * slope, 0.05, 0.95);
  // Var(z(x-1) - 2z(x) + z(x+1)) = 8γ(1) - 2γ(2): a small difference of large
  // terms, unreliable from scattered samples (pair1 pairs at lag 1). Then the
  // fBm form γ(1)(8 - 2·4^H), from γ(1) and the H of all lags (both stable),
  // scaled by kFbmToTerrain: real DEMs are smoother at the cell scale than
  // that extrapolation (also where 8γ(1) - 2γ(2) is not positive).
  const double empirical = 8.0 * g1 - 2.0 * g2;
  const double fbm_form = kFbmToTerrain * g1 * (8.0 - 2.0 * std::pow(4.0, m.H));
  const double trust = empirical > 0 ? smoothstep((pairs1 - kDensePairs / 10) / (0.9 * kDensePairs)) : 0.0;
  m.curvature = trust * empirical + (1.0 - trust) * fbm_form;
  m.valid = m.curvature > 0;
  return m;
}


}  // namespace mcmd::rough

namespace mcmd {

RoughnessModel estimate_roughness(const RoughField& grid) {
  return rough::model_of(rough::variogram_of(rough::pair_sums(grid, rough::block_lattice(grid), 1)));
}

RoughnessModel estimate_roughness(const Grid& grid) { return estimate_roughness(RoughField::of(grid)); }

}  // namespace mcmd
