#include "terrain/methods/measured_relief.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "terrain/methods/fbm.hpp"
#include "thin_plate/thin_plate.hpp"

namespace mcmd::terrain {

namespace {

constexpr int kMaxLag = 64;             // the longest base lag looked for
constexpr double kMinBasePairs = 100;   // pairs at the base lag
constexpr double kMinFitPairs = 30;     // pairs at 2b to fit H, held-out cells to measure a residual
constexpr int kCalibrationSide = 257;   // the relief is calibrated on a corner of at most this side
constexpr int kLocalRadius = 4;         // lattice cells around each over which its residual is averaged
constexpr double kMinScale = 0.05, kMaxScale = 4.0;  // the relief's local factor, bounded

struct Gamma {
  double sum = 0.0, pairs = 0.0;
  double value() const { return pairs > 0 ? 0.5 * sum / pairs : 0.0; }
};

// γ(d) over the row and column pairs (x, y), (x + d, y) and (x, y), (x, y + d)
// of a w×h raster's cells that `use` passes.
template <class Use>
Gamma gamma_at(int w, int h, const std::vector<double>& z, int d, Use use) {
  Gamma g;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const std::size_t i = static_cast<std::size_t>(y) * w + x;
      if (!use(i)) continue;
      if (x + d < w && use(i + d)) {
        const double t = z[i + d] - z[i];
        g.sum += t * t, g.pairs += 1;
      }
      const std::size_t below = i + static_cast<std::size_t>(d) * w;
      if (y + d < h && use(below)) {
        const double t = z[below] - z[i];
        g.sum += t * t, g.pairs += 1;
      }
    }
  return g;
}

// The shortest gap between successive known cells of a row or a column that
// kMinBasePairs pairs have (0: none).
int base_lag(const Canvas& c) {
  std::vector<double> gaps(kMaxLag + 1, 0.0);
  std::vector<int> last_row(static_cast<std::size_t>(c.w), -1);
  for (int y = 0; y < c.h; ++y) {
    int last_col = -1;
    for (int x = 0; x < c.w; ++x) {
      if (c.state[c.index(x, y)] != CellState::known) continue;
      if (last_col >= 0 && x - last_col <= kMaxLag) gaps[x - last_col] += 1;
      if (last_row[x] >= 0 && y - last_row[x] <= kMaxLag) gaps[y - last_row[x]] += 1;
      last_col = x, last_row[x] = y;
    }
  }
  for (int d = 1; d <= kMaxLag; ++d)
    if (gaps[d] >= kMinBasePairs) return d;
  return 0;
}

// A lattice of spacing b through (x0, y0): its cells, as a grid.
struct Lattice {
  int b = 1, x0 = 0, y0 = 0, w = 0, h = 0;
  std::vector<double> z;
  std::vector<CellState> state;
};

// The known cells as a lattice of spacing b > 1, when every one lies on it.
bool known_lattice(const Canvas& c, int b, Lattice& l) {
  int x0 = -1, y0 = -1;
  for (std::size_t i = 0; i < c.cells() && x0 < 0; ++i)
    if (c.state[i] == CellState::known) x0 = static_cast<int>(i % c.w) % b, y0 = static_cast<int>(i / c.w) % b;
  if (b < 2 || x0 < 0) return false;
  for (int y = 0; y < c.h; ++y)
    for (int x = 0; x < c.w; ++x)
      if (c.state[c.index(x, y)] == CellState::known && ((x - x0) % b || (y - y0) % b)) return false;
  l = Lattice{b, x0, y0, (c.w - 1 - x0) / b + 1, (c.h - 1 - y0) / b + 1, {}, {}};
  l.z.resize(static_cast<std::size_t>(l.w) * l.h);
  l.state.resize(l.z.size());
  for (int j = 0; j < l.h; ++j)
    for (int i = 0; i < l.w; ++i) {
      const std::size_t k = c.index(x0 + i * b, y0 + j * b), at = static_cast<std::size_t>(j) * l.w + i;
      l.z[at] = c.z[k];
      l.state[at] = c.state[k] == CellState::known ? CellState::known : CellState::unknown;
    }
  return true;
}

ThinPlateSchedule schedule_of(int threads) {
  ThinPlateSchedule s;
  s.vcycle.threads = threads;
  return s;
}

// The squared residuals, at the cells `held` marks (0 elsewhere), of the thin
// plate through the cells `kept` marks (others unknown) of a w×h field z.
std::vector<double> plate_residuals(int w, int h, const std::vector<double>& z, const std::vector<std::uint8_t>& kept,
                                    const std::vector<std::uint8_t>& held, int threads) {
  std::vector<double> plate(z.size());
  std::vector<CellState> state(z.size());
  for (std::size_t i = 0; i < z.size(); ++i) {
    state[i] = kept[i] ? CellState::known : CellState::unknown;
    plate[i] = kept[i] ? z[i] : 0.0;
  }
  thin_plate_smooth(FieldView{w, h, plate.data(), state.data()}, schedule_of(threads));
  for (std::size_t i = 0; i < z.size(); ++i) plate[i] = held[i] ? (plate[i] - z[i]) * (plate[i] - z[i]) : 0.0;
  return plate;
}

double mean_of(const std::vector<double>& r2, const std::vector<std::uint8_t>& held, double& count) {
  double sum = 0.0;
  count = 0.0;
  for (std::size_t i = 0; i < r2.size(); ++i)
    if (held[i]) sum += r2[i], count += 1;
  return count > 0 ? sum / count : 0.0;
}

// The held-out residuals of a lattice (lattice_residual) averaged over the
// (2r+1)² lattice cells around each: the local residual, `global` where
// fewer than a quarter of those cells were held out.
std::vector<double> local_residual(const Lattice& l, const std::vector<double>& r2, const std::vector<std::uint8_t>& held,
                                   double global) {
  const int W = l.w + 1;
  std::vector<double> sum(static_cast<std::size_t>(W) * (l.h + 1), 0.0), count(sum.size(), 0.0);
  for (int j = 0; j < l.h; ++j)
    for (int i = 0; i < l.w; ++i) {
      const std::size_t a = static_cast<std::size_t>(j + 1) * W + i + 1, k = static_cast<std::size_t>(j) * l.w + i;
      sum[a] = r2[k] + sum[a - 1] + sum[a - W] - sum[a - W - 1];
      count[a] = held[k] + count[a - 1] + count[a - W] - count[a - W - 1];
    }
  const auto box = [&](const std::vector<double>& t, int i0, int j0, int i1, int j1) {
    return t[static_cast<std::size_t>(j1) * W + i1] - t[static_cast<std::size_t>(j0) * W + i1] -
           t[static_cast<std::size_t>(j1) * W + i0] + t[static_cast<std::size_t>(j0) * W + i0];
  };
  std::vector<double> local(r2.size(), global);
  const double enough = 0.25 * (2 * kLocalRadius + 1) * (2 * kLocalRadius + 1);
  for (int j = 0; j < l.h; ++j)
    for (int i = 0; i < l.w; ++i) {
      const int i0 = std::max(0, i - kLocalRadius), j0 = std::max(0, j - kLocalRadius);
      const int i1 = std::min(l.w, i + kLocalRadius + 1), j1 = std::min(l.h, j + kLocalRadius + 1);
      const double n = box(count, i0, j0, i1, j1);
      if (n >= enough) local[static_cast<std::size_t>(j) * l.w + i] = box(sum, i0, j0, i1, j1) / n;
    }
  return local;
}

// sqrt(local / global) at every canvas cell, bilinear between lattice cells
// (clamped beyond them), bounded.
std::vector<double> relief_scale(const Canvas& c, const Lattice& l, const std::vector<double>& local, double global) {
  std::vector<double> node(local.size());
  for (std::size_t k = 0; k < local.size(); ++k)
    node[k] = std::clamp(std::sqrt(std::max(local[k], 0.0) / global), kMinScale, kMaxScale);  // box sums may round below 0
  const auto along = [&](int v, int v0, int n, int& k, double& t) {
    const double u = std::clamp(static_cast<double>(v - v0) / l.b, 0.0, static_cast<double>(n - 1));
    k = std::min(static_cast<int>(u), std::max(0, n - 2));
    t = n > 1 ? u - k : 0.0;
  };
  std::vector<double> scale(c.cells());
  for (int y = 0; y < c.h; ++y) {
    int j = 0;
    double ty = 0.0;
    along(y, l.y0, l.h, j, ty);
    const int j1 = std::min(j + 1, l.h - 1);
    for (int x = 0; x < c.w; ++x) {
      int i = 0;
      double tx = 0.0;
      along(x, l.x0, l.w, i, tx);
      const int i1 = std::min(i + 1, l.w - 1);
      const auto at = [&](int a, int b) { return node[static_cast<std::size_t>(b) * l.w + a]; };
      const double top = at(i, j) + tx * (at(i1, j) - at(i, j)), bottom = at(i, j1) + tx * (at(i1, j1) - at(i, j1));
      scale[c.index(x, y)] = top + ty * (bottom - top);
    }
  }
  return scale;
}

// What a thin plate through every (2s)-th cell of the known lattice misses at
// its other s-th cells whose four (2s)-th neighbours are known: their squared
// residuals (r2) and where they are (held); the mean, -1 when too few.
double lattice_residual(const Lattice& l, int s, int threads, std::vector<double>& r2, std::vector<std::uint8_t>& held) {
  const auto at = [&](int i, int j) { return static_cast<std::size_t>(j) * l.w + i; };
  const auto known = [&](int i, int j) { return i < l.w && j < l.h && l.state[at(i, j)] == CellState::known; };
  std::vector<std::uint8_t> kept(l.z.size(), 0);
  held.assign(l.z.size(), 0);
  for (int j = 0; j < l.h; j += s)
    for (int i = 0; i < l.w; i += s) {
      if (!known(i, j)) continue;
      const int ei = i - i % (2 * s), ej = j - j % (2 * s), e = 2 * s;
      if (ei == i && ej == j) kept[at(i, j)] = 1;
      else held[at(i, j)] = known(ei, ej) && known(ei + e, ej) && known(ei, ej + e) && known(ei + e, ej + e);
    }
  r2 = plate_residuals(l.w, l.h, l.z, kept, held, threads);
  double count = 0.0;
  const double r = mean_of(r2, held, count);
  return count >= kMinFitPairs ? r : -1.0;
}

// The relief's (amplitude 1) residuals as lattice_residual measures the
// terrain's, at s = 1 and 2: on its cells of the b lattice, over a corner of
// the raster whose sides run along the 4b lattice.
std::array<double, 2> relief_residuals(const Canvas& c, const Lattice& l, double H, std::uint64_t seed, int threads) {
  const int enough = std::max(8, (kCalibrationSide - 1) / (4 * l.b));
  const int steps_x = std::max(1, std::min((l.w - 1) / 4, enough)), steps_y = std::max(1, std::min((l.h - 1) / 4, enough));
  Lattice sampled{l.b, l.x0, l.y0, steps_x * 4 + 1, steps_y * 4 + 1, {}, {}};
  const int w = l.x0 + (sampled.w - 1) * l.b + 1, h = l.y0 + (sampled.h - 1) * l.b + 1;
  const int octaves = fbm_octaves(c.w, c.h);
  const std::vector<double> relief = fbm_relief(w, h, seed, H, 1.0, octaves, octaves, threads);
  sampled.state.assign(static_cast<std::size_t>(sampled.w) * sampled.h, CellState::known);
  for (int j = 0; j < sampled.h; ++j)
    for (int i = 0; i < sampled.w; ++i)
      sampled.z.push_back(relief[static_cast<std::size_t>(l.y0 + j * l.b) * w + l.x0 + i * l.b]);
  std::array<double, 2> out{};
  std::vector<double> r2;
  std::vector<std::uint8_t> held;
  for (int s = 1; s <= 2; ++s) out[s - 1] = lattice_residual(sampled, s, threads, r2, held);
  return out;
}

// The relief's (amplitude 1) semivariance at lag b, on a corner of the raster.
double relief_gamma(const Canvas& c, int b, double H, std::uint64_t seed, int threads) {
  const int w = std::min(c.w, kCalibrationSide * 2), h = std::min(c.h, kCalibrationSide * 2);
  const int octaves = fbm_octaves(c.w, c.h);
  const std::vector<double> relief = fbm_relief(w, h, seed, H, 1.0, octaves, octaves, threads);
  return gamma_at(w, h, relief, b, [](std::size_t) { return true; }).value();
}

}  // namespace

MeasuredRelief measure_relief(const Canvas& c, std::uint64_t seed, double fallback_H, int threads) {
  MeasuredRelief m;
  m.lag = base_lag(c);
  if (m.lag == 0)
    throw std::invalid_argument(
        "rs auto measures the roughness of the known terrain (a sketch's, or a DEM's given to -upsample), and "
        "too few of its cells lie in rows or columns here: give a number instead (e.g. -rs 300m, RS=300m)");
  const auto known = [&](std::size_t i) { return c.state[i] == CellState::known; };
  const Gamma at_b = gamma_at(c.w, c.h, c.z, m.lag, known), at_2b = gamma_at(c.w, c.h, c.z, 2 * m.lag, known);
  m.H = fallback_H;
  if (at_2b.pairs >= kMinFitPairs && at_b.value() > 0 && at_2b.value() > 0)
    m.H = std::clamp(std::log2(at_2b.value() / at_b.value()) / 2.0, 0.0, 1.0);
  Lattice l;
  if (known_lattice(c, m.lag, l)) {
    std::vector<double> r2, r2_up;
    std::vector<std::uint8_t> held, held_up;
    const double residual = lattice_residual(l, 1, threads, r2, held);
    const double residual_up = lattice_residual(l, 2, threads, r2_up, held_up);
    if (residual >= 0) {
      m.lattice = true;
      const std::array<double, 2> per_unit = relief_residuals(c, l, m.H, seed, threads);
      // How the residual shrinks from one scale to the next, the terrain's over the relief's.
      const double shrink = residual_up > 0 && per_unit[1] > 0 && per_unit[0] > 0
                                ? (residual / residual_up) / (per_unit[0] / per_unit[1])
                                : 1.0;
      m.amplitude = per_unit[0] > 0 ? std::sqrt(residual * shrink / per_unit[0]) : 0.0;
      if (residual > 0) m.scale = relief_scale(c, l, local_residual(l, r2, held, residual), residual);
      return m;
    }
  }
  const double per_unit = relief_gamma(c, m.lag, m.H, seed, threads);
  m.amplitude = per_unit > 0 ? std::sqrt(at_b.value() / per_unit) : 0.0;
  return m;
}

}  // namespace mcmd::terrain
