#include "mcmd/roughness.hpp"

#include <algorithm>
#include <cmath>

#include "mcmd/noise.hpp"
#include "mcmd/thin_plate.hpp"

namespace mcmd {

namespace {

constexpr int kOctaves = 6;      // spacings 1 .. 32 cells
constexpr double kStrength = 0.85;  // of the terrain's curvature amplitude: measured
                                    // Laplacian spread in voids ≈ 1 (the smooth fill adds some)
constexpr double kGolden = 2.399963229728653;  // golden angle, radians

// Semivariogram at lag d over pairs of constraint cells along x and y.
double semivariogram(const Grid& g, int d, std::size_t& pairs) {
  double sum = 0.0;
  pairs = 0;
  for (int y = 0; y < g.side(); ++y)
    for (int x = 0; x < g.side(); ++x) {
      if (!is_constraint(g.state(x, y))) continue;
      if (x + d < g.side() && is_constraint(g.state(x + d, y))) {
        const double dz = g.z(x + d, y) - g.z(x, y);
        sum += dz * dz;
        ++pairs;
      }
      if (y + d < g.side() && is_constraint(g.state(x, y + d))) {
        const double dz = g.z(x, y + d) - g.z(x, y);
        sum += dz * dz;
        ++pairs;
      }
    }
  return pairs ? 0.5 * sum / static_cast<double>(pairs) : 0.0;
}

double catmull_rom(double p0, double p1, double p2, double p3, double t) {
  return p1 + 0.5 * t * (p2 - p0 + t * (2 * p0 - 5 * p1 + 4 * p2 - p3 + t * (3 * (p1 - p2) + p3 - p0)));
}

// One octave: white noise on a rotated lattice of spacing s, interpolated.
void add_octave(const Grid& g, std::uint64_t seed, int j, double weight, std::vector<double>& out) {
  const double s = std::ldexp(1.0, j);
  const double c = std::cos(j * kGolden) / s, sn = std::sin(j * kGolden) / s;
  const double ox = 0.618 * j, oy = 0.382 * j;
  const auto uv = [&](double gx, double gy, double& u, double& v) {
    u = c * gx + sn * gy + ox;
    v = -sn * gx + c * gy + oy;
  };
  // Node box covering the grid's corners in (u, v).
  const double gx0 = static_cast<double>(g.origin_x()), gy0 = static_cast<double>(g.origin_y());
  const double gx1 = gx0 + g.side() - 1, gy1 = gy0 + g.side() - 1;
  double umin = 1e300, umax = -1e300, vmin = 1e300, vmax = -1e300;
  for (double gx : {gx0, gx1})
    for (double gy : {gy0, gy1}) {
      double u, v;
      uv(gx, gy, u, v);
      umin = std::min(umin, u); umax = std::max(umax, u);
      vmin = std::min(vmin, v); vmax = std::max(vmax, v);
    }
  const long long i0 = static_cast<long long>(std::floor(umin)) - 1, j0 = static_cast<long long>(std::floor(vmin)) - 1;
  const int nu = static_cast<int>(std::floor(umax) - i0) + 3, nv = static_cast<int>(std::floor(vmax) - j0) + 3;
  std::vector<double> node(static_cast<std::size_t>(nu) * nv);
  const std::uint64_t key = seed * 0x9E3779B97F4A7C15ull + static_cast<std::uint64_t>(j + 1);
  for (int b = 0; b < nv; ++b)
    for (int a = 0; a < nu; ++a)
      node[static_cast<std::size_t>(b) * nu + a] = std::sqrt(3.0) * hash_uniform(key, i0 + a, j0 + b);
  for (int y = 0; y < g.side(); ++y)
    for (int x = 0; x < g.side(); ++x) {
      double u, v;
      uv(gx0 + x, gy0 + y, u, v);
      const long long iu = static_cast<long long>(std::floor(u)), iv = static_cast<long long>(std::floor(v));
      const double tu = u - iu, tv = v - iv;
      double col[4];
      for (int r = 0; r < 4; ++r) {
        const double* p = node.data() + static_cast<std::size_t>(iv - 1 + r - j0) * nu + (iu - 1 - i0);
        col[r] = catmull_rom(p[0], p[1], p[2], p[3], tu);
      }
      out[g.index(x, y)] += weight * catmull_rom(col[0], col[1], col[2], col[3], tv);
    }
}

// Variance of second differences along x and y over all cells of `z`.
double curvature_of(const std::vector<double>& z, int side) {
  double sum = 0.0;
  std::size_t n = 0;
  for (int y = 1; y < side - 1; ++y)
    for (int x = 1; x < side - 1; ++x) {
      const std::size_t i = static_cast<std::size_t>(y) * side + x;
      const double dxx = z[i - 1] - 2 * z[i] + z[i + 1], dyy = z[i - side] - 2 * z[i] + z[i + side];
      sum += dxx * dxx + dyy * dyy;
      n += 2;
    }
  return n ? sum / static_cast<double>(n) : 0.0;
}

}  // namespace

RoughnessModel estimate_roughness(const Grid& grid) {
  RoughnessModel m;
  double sx = 0, sy = 0, sxx = 0, sxy = 0, n = 0, g1 = 0, g2 = 0;
  for (int d = 1; d <= 16; d *= 2) {
    std::size_t pairs = 0;
    const double gamma = semivariogram(grid, d, pairs);
    if (pairs < 30 || gamma <= 0) continue;
    if (d == 1) g1 = gamma;
    if (d == 2) g2 = gamma;
    const double lx = std::log(static_cast<double>(d)), ly = std::log(gamma);
    sx += lx; sy += ly; sxx += lx * lx; sxy += lx * ly; n += 1;
  }
  if (n < 2 || g1 <= 0) return m;
  const double slope = (n * sxy - sx * sy) / (n * sxx - sx * sx);  // 2H
  m.H = std::clamp(0.5 * slope, 0.05, 0.95);
  // Var(z(x-1) - 2z(x) + z(x+1)) = 8γ(1) - 2γ(2). Very smooth data can give
  // γ(2) >= 4γ(1); then the fBm form γ(1)(8 - 2·4^H) with the clamped H.
  const double empirical = 8.0 * g1 - 2.0 * g2;
  m.curvature = empirical > 0 ? empirical : g1 * (8.0 - 2.0 * std::pow(4.0, m.H));
  m.valid = m.curvature > 0;
  return m;
}

std::vector<double> fractal_noise(const Grid& grid, std::uint64_t seed, double H, int octaves) {
  std::vector<double> out(grid.cell_count(), 0.0);
  for (int j = 0; j < octaves; ++j) add_octave(grid, seed, j, std::exp2(j * H), out);
  return out;
}

void add_roughness(Grid& grid, const FillParams& params) {
  double H = params.H, scale = 0.0;
  std::vector<double> noise;
  if (params.rs_auto) {
    const RoughnessModel m = estimate_roughness(grid);
    if (!m.valid) return;
    H = m.H;
    noise = fractal_noise(grid, params.seed, H, kOctaves);
    const double c = curvature_of(noise, grid.side());
    scale = c > 0 ? kStrength * std::sqrt(m.curvature / c) : 0.0;
  } else if (params.rs > 0) {
    const double unit = params.noise_unit > 0 ? params.noise_unit : known_range(grid);
    noise = fractal_noise(grid, params.seed, H, kOctaves);
    scale = params.rs * unit * std::exp2(-(kOctaves - 1) * H);  // coarsest octave: rs · unit
  }
  if (scale <= 0) return;
  // Condition on the constraints: subtract the smooth fill of the noise's own
  // constraint values, so the correction is 0 there and grows into the voids.
  Grid cond = grid;
  for (std::size_t i = 0; i < cond.cell_count(); ++i) cond.elevations()[i] = noise[i];
  FillParams smooth = params;
  smooth.rs = 0.0;
  smooth.rs_auto = false;
  thin_plate_fill(cond, smooth);
  for (std::size_t i = 0; i < grid.cell_count(); ++i)
    if (!is_constraint(grid.states()[i])) grid.elevations()[i] += scale * (noise[i] - cond.elevations()[i]);
}

}  // namespace mcmd
