#include "terrain/erosion/pyramid.hpp"

#include <algorithm>
#include <cstddef>

namespace mcmd::terrain {

namespace {

// Full weighting of a fine field at coarse cell (X, Y), clamped at the edges.
double restricted(const std::vector<double>& f, int w, int h, int X, int Y) {
  static constexpr double kW[3] = {0.25, 0.5, 0.25};
  double sum = 0.0;
  for (int dy = -1; dy <= 1; ++dy)
    for (int dx = -1; dx <= 1; ++dx) {
      const int x = std::clamp(2 * X + dx, 0, w - 1), y = std::clamp(2 * Y + dy, 0, h - 1);
      sum += kW[dx + 1] * kW[dy + 1] * f[static_cast<std::size_t>(y) * w + x];
    }
  return sum;
}

// The mean height of the fixed interior cells of g under coarse cell (X, Y);
// false when there is none.
bool fixed_below(const ErosionGrid& g, int X, int Y, double& mean) {
  double sum = 0.0;
  int count = 0;
  for (int dy = -1; dy <= 1; ++dy)
    for (int dx = -1; dx <= 1; ++dx) {
      const int x = 2 * X + dx, y = 2 * Y + dy;
      if (x < 0 || y < 0 || x >= g.w || y >= g.h || on_border(x, y, g.w, g.h)) continue;
      const std::size_t j = static_cast<std::size_t>(y) * g.w + x;
      if (g.fixed[j]) sum += g.initial[j], ++count;
    }
  if (count) mean = sum / count;
  return count > 0;
}

// Catmull-Rom along one line: fine cell i of n from coarse cells (stride cs).
void prolong_line(const double* c, int cn, std::ptrdiff_t cs, double* f, int n, std::ptrdiff_t fs) {
  const auto at = [&](int k) { return c[std::clamp(k, 0, cn - 1) * cs]; };
  for (int i = 0; i < n; ++i) {
    const int k = i / 2;
    f[i * fs] = i % 2 == 0 ? at(k) : (9.0 * (at(k) + at(k + 1)) - at(k - 1) - at(k + 2)) / 16.0;
  }
}

}  // namespace

ErosionGrid coarser(const ErosionGrid& g) {
  ErosionGrid c;
  c.w = g.w / 2 + 1, c.h = g.h / 2 + 1;
  c.spacing = 2.0 * g.spacing;
  c.margin = (g.margin + 1) / 2;
  const std::size_t n = static_cast<std::size_t>(c.w) * c.h;
  c.initial.resize(n), c.uplift.resize(n), c.fixed.assign(n, 0);
  for (int Y = 0; Y < c.h; ++Y)
    for (int X = 0; X < c.w; ++X) {
      const std::size_t i = static_cast<std::size_t>(Y) * c.w + X;
      c.initial[i] = restricted(g.initial, g.w, g.h, X, Y);
      c.uplift[i] = restricted(g.uplift, g.w, g.h, X, Y);
      double mean;
      if (fixed_below(g, X, Y, mean)) c.fixed[i] = 2, c.initial[i] = mean;
      if (on_border(X, Y, c.w, c.h)) c.fixed[i] = std::max<std::uint8_t>(c.fixed[i], 1);
      if (!g.guides.divide.empty()) {
        if (c.guides.divide.empty()) c.guides.divide.assign(n, 0);
        for (int dy = -1; dy <= 1; ++dy)
          for (int dx = -1; dx <= 1; ++dx) {
            const int x = 2 * X + dx, y = 2 * Y + dy;
            if (x >= 0 && y >= 0 && x < g.w && y < g.h && g.guides.divide[static_cast<std::size_t>(y) * g.w + x])
              c.guides.divide[i] = 1;
          }
      }
      // Full weighting gives a line of sources s a coarse cell s/2: the two
      // fine cells under it (2s fine cells of area) in coarse cells.
      if (!g.guides.source.empty()) {
        if (c.guides.source.empty()) c.guides.source.assign(n, 0.0);
        c.guides.source[i] = restricted(g.guides.source, g.w, g.h, X, Y);
      }
    }
  return c;
}

std::vector<double> restrict_field(const std::vector<double>& field, int w, int h) {
  const int cw = w / 2 + 1, ch = h / 2 + 1;
  std::vector<double> out(static_cast<std::size_t>(cw) * ch);
  for (int Y = 0; Y < ch; ++Y)
    for (int X = 0; X < cw; ++X) out[static_cast<std::size_t>(Y) * cw + X] = restricted(field, w, h, X, Y);
  return out;
}

std::vector<double> prolong(const std::vector<double>& field, int cw, int ch, int w, int h) {
  std::vector<double> rows(static_cast<std::size_t>(w) * ch), out(static_cast<std::size_t>(w) * h);
  for (int Y = 0; Y < ch; ++Y)
    prolong_line(field.data() + static_cast<std::size_t>(Y) * cw, cw, 1, rows.data() + static_cast<std::size_t>(Y) * w,
                 w, 1);
  for (int x = 0; x < w; ++x) prolong_line(rows.data() + x, ch, w, out.data() + x, h, w);
  return out;
}

}  // namespace mcmd::terrain
