#include "mcmd/lattice.hpp"

namespace mcmd {

std::size_t Lattice::free_count() const {
  std::size_t n = 0;
  for (const Span& s : spans) n += static_cast<std::size_t>(s.x1 - s.x0);
  return n;
}

std::vector<Span> free_spans(const std::vector<std::uint8_t>& pinned, int side) {
  std::vector<Span> out;
  for (int y = 0; y < side; ++y) {
    const std::uint8_t* row = pinned.data() + static_cast<std::size_t>(y) * side;
    int x = 0;
    while (x < side) {
      while (x < side && row[x]) ++x;
      const int x0 = x;
      while (x < side && !row[x]) ++x;
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
      if (fx < 0 || fy < 0 || fx >= fine.side || fy >= fine.side) continue;
      if (fine.pinned[fine.index(fx, fy)]) return true;
    }
  return false;
}

}  // namespace

Lattice coarser_lattice(const Lattice& fine, CoarsePin rule) {
  Lattice c;
  c.side = (fine.side + 1) / 2;
  c.tension = 4.0 * fine.tension;
  const std::size_t cells = static_cast<std::size_t>(c.side) * c.side;
  c.z.assign(cells, 0.0);
  c.pinned.assign(cells, 0);
  for (int j = 0; j < c.side; ++j)
    for (int i = 0; i < c.side; ++i) {
      const std::size_t f = fine.index(2 * i, 2 * j);
      const bool pin = rule == CoarsePin::position ? fine.pinned[f] != 0 : any_pinned_around(fine, 2 * i, 2 * j);
      if (!pin) continue;
      c.pinned[c.index(i, j)] = 1;
      c.z[c.index(i, j)] = fine.z[f];
    }
  c.spans = free_spans(c.pinned, c.side);
  return c;
}

}  // namespace mcmd
