#include "thin_plate/direct_plate.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace mcmd {

namespace {

// The second differences of the energy, by the cell they are keyed on: z_xx
// and z_yy centred there, z_xy on the 2×2 block whose top-left cell it is.
enum Kind : std::uint64_t { xx = 0, yy = 1, xy = 2 };

struct Term {
  std::size_t cell[4];
  double coef[4];
  int size;
  double weight;
};

// Every term of the energy that involves cell (x, y) and fits in the field,
// as keys kind · cells + key cell.
void terms_of(int x, int y, int w, int h, std::vector<std::uint64_t>& keys) {
  const auto key = [&](Kind k, int kx, int ky) {
    keys.push_back(k * static_cast<std::uint64_t>(w) * h + static_cast<std::uint64_t>(ky) * w + kx);
  };
  for (int cx = x - 1; cx <= x + 1; ++cx)
    if (cx >= 1 && cx + 1 < w) key(xx, cx, y);
  for (int cy = y - 1; cy <= y + 1; ++cy)
    if (cy >= 1 && cy + 1 < h) key(yy, x, cy);
  for (int by = y - 1; by <= y; ++by)
    for (int bx = x - 1; bx <= x; ++bx)
      if (bx >= 0 && by >= 0 && bx + 1 < w && by + 1 < h) key(xy, bx, by);
}

Term term_of(std::uint64_t key, int w, int h) {
  const std::uint64_t cells = static_cast<std::uint64_t>(w) * h;
  const auto kind = static_cast<Kind>(key / cells);
  const std::size_t c = key % cells;
  const std::size_t W = static_cast<std::size_t>(w);
  switch (kind) {
    case xx: return Term{{c - 1, c, c + 1, 0}, {1, -2, 1, 0}, 3, 1.0};
    case yy: return Term{{c - W, c, c + W, 0}, {1, -2, 1, 0}, 3, 1.0};
    default: return Term{{c, c + 1, c + W, c + W + 1}, {1, -1, -1, 1}, 4, 2.0};
  }
}

// In place: the Cholesky factor L of the n×n SPD matrix a (row-major, lower
// triangle used), then x = a⁻¹ b. False when a pivot is not clearly
// positive (the plate is not held: a null direction of the energy).
bool cholesky_solve(std::vector<double>& a, std::vector<double>& b, std::size_t n) {
  double largest = 0.0;
  for (std::size_t i = 0; i < n; ++i) largest = std::max(largest, a[i * n + i]);
  for (std::size_t j = 0; j < n; ++j) {
    double d = a[j * n + j];
    for (std::size_t k = 0; k < j; ++k) d -= a[j * n + k] * a[j * n + k];
    if (!(d > 1e-10 * largest)) return false;
    const double l = std::sqrt(d);
    a[j * n + j] = l;
    for (std::size_t i = j + 1; i < n; ++i) {
      double s = a[i * n + j];
      for (std::size_t k = 0; k < j; ++k) s -= a[i * n + k] * a[j * n + k];
      a[i * n + j] = s / l;
    }
  }
  for (std::size_t i = 0; i < n; ++i) {  // L y = b
    for (std::size_t k = 0; k < i; ++k) b[i] -= a[i * n + k] * b[k];
    b[i] /= a[i * n + i];
  }
  for (std::size_t i = n; i-- > 0;) {  // Lᵀ x = y
    for (std::size_t k = i + 1; k < n; ++k) b[i] -= a[k * n + i] * b[k];
    b[i] /= a[i * n + i];
  }
  return true;
}

}  // namespace

bool direct_thin_plate(int w, int h, double* z, const CellState* state, std::size_t max_unknown) {
  std::vector<std::size_t> unknown;  // in raster order: sorted
  for (std::size_t i = 0; i < static_cast<std::size_t>(w) * h; ++i) {
    if (is_constraint(state[i])) continue;
    if (unknown.size() == max_unknown) return false;
    unknown.push_back(i);
  }
  const std::size_t n = unknown.size();
  if (n == 0) return false;
  std::vector<std::uint64_t> keys;
  for (std::size_t i : unknown) terms_of(static_cast<int>(i % w), static_cast<int>(i / w), w, h, keys);
  std::sort(keys.begin(), keys.end());
  keys.erase(std::unique(keys.begin(), keys.end()), keys.end());

  // ½ ∂²E/∂z² over the unknown cells, and the right-hand side from the
  // constraint cells each term reaches.
  std::vector<double> a(n * n, 0.0), b(n, 0.0);
  for (std::uint64_t key : keys) {
    const Term t = term_of(key, w, h);
    double fixed = 0.0;
    std::size_t at[4];
    for (int k = 0; k < t.size; ++k) {
      const auto it = std::lower_bound(unknown.begin(), unknown.end(), t.cell[k]);
      const bool free = it != unknown.end() && *it == t.cell[k];
      at[k] = free ? static_cast<std::size_t>(it - unknown.begin()) : n;
      if (!free) fixed += t.coef[k] * z[t.cell[k]];
    }
    for (int k = 0; k < t.size; ++k) {
      if (at[k] == n) continue;
      b[at[k]] -= t.weight * t.coef[k] * fixed;
      for (int l = 0; l < t.size; ++l)
        if (at[l] != n && at[l] <= at[k]) a[at[k] * n + at[l]] += t.weight * t.coef[k] * t.coef[l];
    }
  }
  if (!cholesky_solve(a, b, n)) return false;
  for (std::size_t k = 0; k < n; ++k) z[unknown[k]] = b[k];
  return true;
}

}  // namespace mcmd
