#include "paper/midpoint_displacement.hpp"

#include <array>
#include <cmath>

#include "paper/butterfly.hpp"
#include "paper/delta.hpp"
#include "paper/mdbu.hpp"
#include "paper/subdivision.hpp"
#include "roughness/noise.hpp"

namespace mcmd {

void seed_roots(std::vector<double>& z, std::vector<std::uint8_t>& fixed,
                std::span<const std::uint32_t> roots) {
  double sum = 0.0;
  std::size_t count = 0;
  for (std::uint32_t r : roots)
    if (fixed[r]) sum += z[r], ++count;
  if (count == 0)
    for (std::size_t i = 0; i < z.size(); ++i)
      if (fixed[i]) sum += z[i], ++count;
  const double start = count ? sum / static_cast<double>(count) : 0.0;
  for (std::uint32_t r : roots)
    if (!fixed[r]) z[r] = start, fixed[r] = 1;
}

namespace {

// What a level's cells share: a parent lies h away along an axis or h·√2
// along a diagonal, so its Δ weight depends on that and on its state only,
// and the displacement's level factor is one number (computed once: the
// same values, hence bits, as per cell).
struct LevelWeights {
  double d_axis = 0.0, d_diag = 0.0;
  std::array<double, 4> w_axis{}, w_diag{};  // per CellState
  double noise_scale = 0.0;                  // 2^(−r · 2 · H), eq. 1
};

struct LevelContext {
  Grid& grid;
  std::vector<std::uint8_t>& fixed;
  Scheme scheme;
  const FillParams& params;
  double noise_unit;
  double dmax;
  double top_half_spacing;
  UniformHash noise;
  LevelWeights level{};
};

void start_level(LevelContext& c, int level) {
  const int h = half_spacing(level, c.grid.levels());
  LevelWeights& l = c.level;
  l.d_axis = std::hypot(h, 0);
  l.d_diag = std::hypot(h, h);
  for (int s = 0; s < 4; ++s) {
    const double I = shape_for(c.params, static_cast<CellState>(s)).I;
    l.w_axis[s] = delta_weight(I, l.d_axis, c.dmax);
    l.w_diag[s] = delta_weight(I, l.d_diag, c.dmax);
  }
  l.noise_scale = std::exp2(-level * 2 * c.params.H);
}

// Interpolate one unset cell from its parents and displace it.
void displace_cell(LevelContext& c, int x, int y, int level) {
  if (c.fixed[c.grid.index(x, y)]) return;
  const int n = c.grid.levels();
  const Parents p = parents_of(c.scheme, x, y, n);
  std::array<double, 4> e{}, w{};
  double nearest = INFINITY;
  for (int i = 0; i < p.count; ++i) {
    const CellXY q = p.cell[i];
    const bool diagonal = q.x != x && q.y != y;
    const auto s = static_cast<std::size_t>(c.grid.state(q.x, q.y));
    e[i] = c.grid.z(q.x, q.y);
    w[i] = diagonal ? c.level.w_diag[s] : c.level.w_axis[s];
    nearest = std::min(nearest, diagonal ? c.level.d_diag : c.level.d_axis);
  }
  double value = 0.0;
  if (c.scheme != Scheme::butterfly || !butterfly_value(c.grid, x, y, half_spacing(level, n), value))
    value = combine_weighted(c.params.delta_form, e.data(), w.data(), p.count);
  if (c.params.rs > 0) {
    // paper_delta(), with its hash and level factor made once
    const double delta = (c.noise(c.grid.origin_x() + x, c.grid.origin_y() + y) + c.params.rt) * c.params.rs *
                         c.level.noise_scale;
    value += nearest / c.top_half_spacing * delta * c.noise_unit;  // the paper's d·δ
  }
  c.grid.z(x, y) = value;
  c.fixed[c.grid.index(x, y)] = 1;
}

// One pass over the cells of `level` with x/h and y/h of the given parities
// (odd = true means an odd multiple of h).
void level_pass(LevelContext& c, int level, bool x_odd, bool y_odd) {
  const int h = half_spacing(level, c.grid.levels());
  const int side = c.grid.side();
  for (int y = y_odd ? h : 0; y < side; y += 2 * h)
    for (int x = x_odd ? h : 0; x < side; x += 2 * h) displace_cell(c, x, y, level);
}

}  // namespace

void midpoint_displacement(Grid& grid, std::vector<std::uint8_t>& fixed, Scheme scheme,
                           const FillParams& params, double noise_unit, const ProgressFn& progress) {
  const int n = grid.levels();
  const std::uint32_t last = static_cast<std::uint32_t>(grid.side() - 1);
  const std::uint32_t side = static_cast<std::uint32_t>(grid.side());
  const std::array<std::uint32_t, 4> corners{0, last, last * side, last * side + last};
  seed_roots(grid.elevations(), fixed, corners);

  LevelContext c{grid, fixed, scheme, params, noise_unit, dmax_for(grid, params),
                 n > 0 ? static_cast<double>(half_spacing(0, n)) : 1.0, UniformHash(params.seed)};
  for (int level = 0; level < n; ++level) {
    start_level(c, level);
    // Square centres first: diamond-square edge midpoints use them as parents;
    // triangle-edge uses only coarser cells, so the order does not matter there.
    level_pass(c, level, true, true);
    level_pass(c, level, true, false);
    level_pass(c, level, false, true);
    report(progress, static_cast<double>(level + 1) / n);
  }
}

}  // namespace mcmd
