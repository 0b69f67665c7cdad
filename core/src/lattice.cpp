#include "mcmd/lattice.hpp"

namespace mcmd {

std::size_t Lattice::free_count() const {
  std::size_t n = 0;
  for (const Span& s : spans) n += static_cast<std::size_t>(s.x1 - s.x0);
  return n;
}

bool banded(const Lattice& lat) { return lat.h > 2 * kBandRows && lat.free_count() >= kBandedMinFree; }

std::vector<std::size_t> band_starts(const Lattice& lat) {
  const int bands = (lat.h + kBandRows - 1) / kBandRows;
  std::vector<std::size_t> start(static_cast<std::size_t>(bands) + 1, lat.spans.size());
  std::size_t k = 0;
  for (int b = 0; b < bands; ++b) {
    while (k < lat.spans.size() && lat.spans[k].y < b * kBandRows) ++k;
    start[b] = k;
  }
  return start;
}

std::vector<Span> free_spans(const std::vector<std::uint8_t>& pinned, int w, int h) {
  std::vector<Span> out;
  for (int y = 0; y < h; ++y) {
    const std::uint8_t* row = pinned.data() + static_cast<std::size_t>(y) * w;
    int x = 0;
    while (x < w) {
      while (x < w && row[x]) ++x;
      const int x0 = x;
      while (x < w && !row[x]) ++x;
      if (x > x0) out.push_back({y, x0, x});
    }
  }
  return out;
}

namespace {

bool any_pinned_around(const Lattice& fine, int x, int y) {
  for (int dy = -1; dy <= 1; ++dy)
    for (int dx = -1; dx <= 1; ++dx) {
      const int fx = x + dx, fy = y + dy;
      if (fx < 0 || fy < 0 || fx >= fine.w || fy >= fine.h) continue;
      if (fine.pinned[fine.index(fx, fy)]) return true;
    }
  return false;
}

}  // namespace

Lattice coarser_lattice(const Lattice& fine, CoarsePin rule) {
  Lattice c;
  c.w = coarser_extent(fine.w);
  c.h = coarser_extent(fine.h);
  c.tension = 4.0 * fine.tension;
  const std::size_t cells = static_cast<std::size_t>(c.w) * c.h;
  c.z.assign(cells, 0.0);
  c.pinned.assign(cells, 0);
  for (int j = 0; j < c.h; ++j)
    for (int i = 0; i < c.w; ++i) {
      const int fx = 2 * i, fy = 2 * j;
      const bool inside = fx < fine.w && fy < fine.h;
      bool pin = false;
      if (rule == CoarsePin::position)
        pin = inside && fine.pinned[fine.index(fx, fy)] != 0;
      else
        pin = any_pinned_around(fine, fx, fy);
      if (!pin) continue;
      c.pinned[c.index(i, j)] = 1;
      // A ghost cell pinned by its neighbourhood holds a correction of 0.
      if (inside) c.z[c.index(i, j)] = fine.z[fine.index(fx, fy)];
    }
  c.spans = free_spans(c.pinned, c.w, c.h);
  return c;
}

}  // namespace mcmd
