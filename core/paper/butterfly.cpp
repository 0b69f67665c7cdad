#include "paper/butterfly.hpp"

#include <array>

#include "paper/subdivision.hpp"

namespace mcmd {

namespace {

struct Offset {
  int dx, dy;  // in half-spacings
};

// A horizontal edge's stencil, as offsets from its midpoint: ends, opposite
// vertices, wings. A vertical edge swaps dx and dy (the NW-SE triangulation
// is symmetric about the main diagonal).
constexpr std::array<Offset, 8> kHorizontal{{{-1, 0}, {1, 0}, {1, 2}, {-1, -2}, {-1, 2}, {3, 2}, {-3, -2}, {1, -2}}};
// The NW-SE diagonal edge through a square centre.
constexpr std::array<Offset, 8> kDiagonal{{{-1, -1}, {1, 1}, {1, -1}, {-1, 1}, {-1, -3}, {3, 1}, {-3, -1}, {1, 3}}};
constexpr std::array<double, 8> kWeights{0.5, 0.5, 2 * kButterflyW, 2 * kButterflyW, -kButterflyW, -kButterflyW,
                                         -kButterflyW, -kButterflyW};

}  // namespace

bool butterfly_value(const Grid& grid, int x, int y, int h, double& out) {
  const bool diagonal = is_square_centre(x, y, h);
  const bool vertical = !diagonal && !((x / h) & 1);
  const std::array<Offset, 8>& stencil = diagonal ? kDiagonal : kHorizontal;
  double sum = 0.0;
  for (int k = 0; k < 8; ++k) {
    const int dx = vertical ? stencil[k].dy : stencil[k].dx;
    const int dy = vertical ? stencil[k].dx : stencil[k].dy;
    const int px = x + dx * h, py = y + dy * h;
    if (!grid.contains(px, py)) return false;
    sum += kWeights[k] * grid.z(px, py);
  }
  out = sum;
  return true;
}

}  // namespace mcmd
