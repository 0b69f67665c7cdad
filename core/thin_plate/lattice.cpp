#include "thin_plate/lattice.hpp"

#include "common/zero_runs.hpp"

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
    detail::for_each_zero_run(row, w, [&](int x0, int x1) { out.push_back({y, x0, x1}); });
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
  if (rule == CoarsePin::position) {
    // Cell (i, j) is fine cell (2i, 2j); ghost cells past the fine lattice stay free.
    const int inside_w = (fine.w + 1) / 2, inside_h = (fine.h + 1) / 2;
    for (int j = 0; j < inside_h; ++j) {
      const std::uint8_t* fine_pin = fine.pinned.data() + fine.index(0, 2 * j);
      const double* fine_z = fine.z.data() + fine.index(0, 2 * j);
      std::uint8_t* pin = c.pinned.data() + c.index(0, j);
      double* z = c.z.data() + c.index(0, j);
      for (int i = 0; i < inside_w; ++i) {  // a select per cell: it vectorises
        const bool pinned = fine_pin[2 * i] != 0;
        pin[i] = pinned;
        z[i] = pinned ? fine_z[2 * i] : 0.0;
      }
    }
  } else {
    for (int j = 0; j < c.h; ++j)
      for (int i = 0; i < c.w; ++i) {
        const int fx = 2 * i, fy = 2 * j;
        if (!any_pinned_around(fine, fx, fy)) continue;
        c.pinned[c.index(i, j)] = 1;
        // A ghost cell pinned by its neighbourhood holds a correction of 0.
        if (fx < fine.w && fy < fine.h) c.z[c.index(i, j)] = fine.z[fine.index(fx, fy)];
      }
  }
  c.spans = free_spans(c.pinned, c.w, c.h);
  return c;
}

}  // namespace mcmd
