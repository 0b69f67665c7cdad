#include "thin_plate/biharmonic_relax.hpp"

#include <algorithm>
#include <cstddef>

namespace mcmd {

namespace {

// The spring on free cell i (0: none).
inline double spring_at(const Lattice& lat, std::size_t i) { return lat.spring.empty() ? lat.spring_all : lat.spring[i]; }

// Interior cells (2 <= x <= w-3, 2 <= y <= h-3): every term fits, the 13-point stencil.
inline double interior_az(const double* z, std::ptrdiff_t s, std::size_t i, double t) {
  const double* c = z + i;
  const double n4 = c[-1] + c[1] + c[-s] + c[s];
  return (20.0 + 4.0 * t) * c[0] - (8.0 + t) * n4 +
         2.0 * (c[-s - 1] + c[-s + 1] + c[s - 1] + c[s + 1]) + (c[-2] + c[2] + c[-2 * s] + c[2 * s]);
}

// The contributions of the second differences along one axis through the cell:
// centres p-1, p, p+1 of that axis, counted when they lie in [1, n-2].
inline void axis_terms(const double* c, std::ptrdiff_t step, int pos, int n, ThinPlateRow& row) {
  if (pos - 1 >= 1) {
    row.az += c[-2 * step] - 2.0 * c[-step] + c[0];
    row.diag += 1.0;
  }
  if (pos >= 1 && pos <= n - 2) {
    row.az += -2.0 * (c[-step] - 2.0 * c[0] + c[step]);
    row.diag += 4.0;
  }
  if (pos + 1 <= n - 2) {
    row.az += c[0] - 2.0 * c[step] + c[2 * step];
    row.diag += 1.0;
  }
}

}  // namespace

ThinPlateRow thin_plate_row(const double* z, int w, int h, int x, int y, double tension) {
  const std::ptrdiff_t s = w;
  const double* c = z + static_cast<std::ptrdiff_t>(y) * s + x;
  ThinPlateRow row;
  if (tension > 0) {
    const auto edge = [&](bool inside, std::ptrdiff_t off) {
      if (!inside) return;
      row.az += tension * (c[0] - c[off]);
      row.diag += tension;
    };
    edge(x > 0, -1);
    edge(x < w - 1, 1);
    edge(y > 0, -s);
    edge(y < h - 1, s);
  }
  axis_terms(c, 1, x, w, row);
  axis_terms(c, s, y, h, row);
  // 2×2 blocks with top-left (bx, by); the cell's sign is + on the block's
  // main diagonal, - on the other. Weight 2 for the mixed term.
  for (int dy = -1; dy <= 0; ++dy) {
    if (y + dy < 0 || y + dy > h - 2) continue;
    for (int dx = -1; dx <= 0; ++dx) {
      if (x + dx < 0 || x + dx > w - 2) continue;
      const double* b = c + dy * s + dx;
      const double t = b[0] - b[1] - b[s] + b[s + 1];
      const double sign = (dx == dy) ? 1.0 : -1.0;
      row.az += 2.0 * sign * t;
      row.diag += 2.0;
    }
  }
  return row;
}


namespace {

// One Gauss-Seidel/SOR update of every cell of a run of interior cells
// [x0, x1) on row y. The left neighbours just updated are carried in
// registers: the loop-carried chain is then one multiply-add per cell.
// With springs (soft data term) the diagonal is 20 + spring and the target
// joins the right-hand side.
void relax_interior_run(Lattice& lat, std::size_t i0, int count, const double* rhs, double omega) {
  const std::ptrdiff_t s = lat.w;
  double* c = lat.z.data() + i0;
  const double* spring = lat.spring.empty() ? nullptr : lat.spring.data() + i0;
  const double* target = lat.target.empty() ? nullptr : lat.target.data() + i0;
  const double ten = lat.tension, diag = 20.0 + 4.0 * ten, near = 8.0 + ten;
  const double all = lat.spring_all, inv_all = omega / (diag + all);
  double w2 = c[-2], w1 = c[-1];
  for (int t = 0; t < count; ++t, ++c) {
    double b = rhs ? rhs[i0 + t] : 0.0;
    double inv = inv_all;
    if (spring) {
      if (target) b += spring[t] * target[t];
      inv = omega / (diag + spring[t]);
    } else if (target) {
      b += all * target[t];
    }
    // Everything but the left neighbour, which is on the chain: written so the
    // chain is one multiply-add (the compiler may not reassociate).
    const double rest = near * (c[1] + c[-s] + c[s]) - 2.0 * (c[-s - 1] + c[-s + 1] + c[s - 1] + c[s + 1]) -
                        (c[2] + c[-2 * s] + c[2 * s]) + b - w2;
    const double pre = (1.0 - omega) * c[0] + inv * rest;
    const double zn = pre + (near * inv) * w1;
    c[0] = zn;
    w2 = w1;
    w1 = zn;
  }
}

void relax_border_cell(Lattice& lat, const double* rhs, int x, int y, double omega) {
  const std::size_t i = lat.index(x, y);
  ThinPlateRow r = thin_plate_row(lat.z.data(), lat.w, lat.h, x, y, lat.tension);
  if (const double k = spring_at(lat, i); k != 0.0) {
    r.az += k * (lat.z[i] - (lat.target.empty() ? 0.0 : lat.target[i]));
    r.diag += k;
  }
  if (r.diag > 0) lat.z[i] += omega * ((rhs ? rhs[i] : 0.0) - r.az) / r.diag;
}

}  // namespace

namespace {

void relax_span(Lattice& lat, const double* rhs, const Span& sp, double omega) {
  const int w = lat.w, h = lat.h;
  if (sp.y < 2 || sp.y > h - 3) {
    for (int x = sp.x0; x < sp.x1; ++x) relax_border_cell(lat, rhs, x, sp.y, omega);
    return;
  }
  // Split the run into border cells on the left, interior, border on the right.
  const int a = std::max(sp.x0, 2), b = std::min(sp.x1, w - 2);
  for (int x = sp.x0; x < std::min(sp.x1, 2); ++x) relax_border_cell(lat, rhs, x, sp.y, omega);
  if (b > a) relax_interior_run(lat, lat.index(a, sp.y), b - a, rhs, omega);
  for (int x = std::max({sp.x0, w - 2, a}); x < sp.x1; ++x) relax_border_cell(lat, rhs, x, sp.y, omega);
}

}  // namespace

void relax(Lattice& lat, const double* rhs, int sweeps, double omega, int threads) {
  if (!banded(lat)) {
    for (int k = 0; k < sweeps; ++k)
      for (const Span& sp : lat.spans) relax_span(lat, rhs, sp, omega);
    return;
  }
  const std::vector<std::size_t> start = band_starts(lat);
  const int bands = static_cast<int>(start.size()) - 1;
  for (int k = 0; k < sweeps; ++k)
    for (int phase = 0; phase < 2; ++phase) {
      const int count = (bands - phase + 1) / 2;
#pragma omp parallel for num_threads(threads) schedule(static, 1) if (threads > 1)
      for (int c = 0; c < count; ++c) {
        const int b = phase + 2 * c;
        for (std::size_t i = start[b]; i < start[b + 1]; ++i) relax_span(lat, rhs, lat.spans[i], omega);
      }
    }
}

double residual_at(const Lattice& lat, const double* rhs, int x, int y) {
  const std::size_t i = lat.index(x, y);
  const bool inside = x >= 2 && y >= 2 && x <= lat.w - 3 && y <= lat.h - 3;
  double az = inside ? interior_az(lat.z.data(), lat.w, i, lat.tension)
                     : thin_plate_row(lat.z.data(), lat.w, lat.h, x, y, lat.tension).az;
  if (const double k = spring_at(lat, i); k != 0.0) az += k * (lat.z[i] - (lat.target.empty() ? 0.0 : lat.target[i]));
  return (rhs ? rhs[i] : 0.0) - az;
}

void residual_run(const Lattice& lat, const double* rhs, const Span& sp, double* out) {
  const bool inner_row = sp.y >= 2 && sp.y <= lat.h - 3;
  const int a = inner_row ? std::max(sp.x0, 2) : sp.x1, b = inner_row ? std::min(sp.x1, lat.w - 2) : sp.x1;
  for (int x = sp.x0; x < std::min(a, sp.x1); ++x) out[x - sp.x0] = residual_at(lat, rhs, x, sp.y);
  if (b > a) {
    // Interior cells: the 13-point stencil with no branch, so the loop vectorises.
    const std::size_t i0 = lat.index(a, sp.y);
    const double* z = lat.z.data();
    const std::ptrdiff_t s = lat.w;
    const double t = lat.tension;
    double* o = out + (a - sp.x0);
    const int n = b - a;
    for (int k = 0; k < n; ++k) o[k] = -interior_az(z, s, i0 + k, t);
    if (rhs)
      for (int k = 0; k < n; ++k) o[k] += rhs[i0 + k];
    // The soft data term, per-cell or uniform springs: one loop per kind, so
    // each still vectorises.
    const auto springs = [&](auto spring_of) {
      if (lat.target.empty()) {
        for (int k = 0; k < n; ++k) o[k] -= spring_of(k) * z[i0 + k];
      } else {
        const double* tg = lat.target.data() + i0;
        for (int k = 0; k < n; ++k) o[k] -= spring_of(k) * (z[i0 + k] - tg[k]);
      }
    };
    if (!lat.spring.empty()) {
      const double* per_cell = lat.spring.data() + i0;
      springs([per_cell](int k) { return per_cell[k]; });
    } else if (const double all = lat.spring_all; all != 0.0) {
      springs([all](int) { return all; });
    }
  }
  for (int x = std::max(b, a); x < sp.x1; ++x) out[x - sp.x0] = residual_at(lat, rhs, x, sp.y);
}

void residual(const Lattice& lat, const double* rhs, std::vector<double>& r, int threads) {
  const std::ptrdiff_t n = static_cast<std::ptrdiff_t>(lat.spans.size());
  threads = team(lat, threads);
#pragma omp parallel for num_threads(threads) schedule(static) if (threads > 1)
  for (std::ptrdiff_t k = 0; k < n; ++k) {
    const Span& sp = lat.spans[static_cast<std::size_t>(k)];
    residual_run(lat, rhs, sp, r.data() + lat.index(sp.x0, sp.y));
  }
}

}  // namespace mcmd
