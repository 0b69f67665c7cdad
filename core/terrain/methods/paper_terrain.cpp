#include "terrain/methods/paper_terrain.hpp"

#include <bit>
#include <vector>

#include "common/grid.hpp"
#include "paper/mdbu.hpp"
#include "paper/midpoint_displacement.hpp"
#include "terrain/methods/mdi.hpp"

namespace mcmd::terrain {

namespace {

// n of the smallest 2^n + 1 >= side.
int levels_covering(int side) { return side <= 2 ? 0 : std::bit_width(static_cast<unsigned>(side - 2)); }

Grid grid_of(const Canvas& c, std::vector<std::uint8_t>& fixed) {
  Grid g(levels_covering(c.w > c.h ? c.w : c.h));
  fixed.assign(g.cell_count(), 0);
  for (int y = 0; y < c.h; ++y)
    for (int x = 0; x < c.w; ++x) {
      const std::size_t i = c.index(x, y);
      g.z(x, y) = c.z[i];
      g.state(x, y) = c.state[i];
      fixed[g.index(x, y)] = is_constraint(c.state[i]);
    }
  return g;
}

// MDI's top-down pass had no interpolation shape.
FillParams without_shapes(FillParams p) {
  p.known_shape = p.ridge_shape = p.river_shape = StateShape{};
  return p;
}

}  // namespace

Scheme scheme_of(TerrainScheme s) {
  switch (s) {
    case TerrainScheme::triangle_edge: return Scheme::triangle_edge;
    case TerrainScheme::butterfly: return Scheme::butterfly;
    default: return Scheme::diamond_square;
  }
}

void paper_terrain(Canvas& c, const TerrainParams& p, double unit, const ProgressFn& progress) {
  std::vector<std::uint8_t> fixed;
  Grid g = grid_of(c, fixed);
  const Scheme scheme = scheme_of(p.scheme);
  const bool old = p.method == TerrainMethod::mdi;
  const FillParams params = old ? without_shapes(p.fill) : p.fill;
  if (c.constraints() > 0) {
    const ProgressFn up = sub_progress(progress, 0.0, 0.5);
    if (old)
      mdi(g, fixed, scheme, params, unit, up);
    else
      mdbu(g, fixed, scheme, params, up);
  }
  midpoint_displacement(g, fixed, scheme, params, unit, sub_progress(progress, 0.5, 1.0));
  for (int y = 0; y < c.h; ++y)
    for (int x = 0; x < c.w; ++x)
      if (!is_constraint(c.state[c.index(x, y)])) c.z[c.index(x, y)] = g.z(x, y);
}

}  // namespace mcmd::terrain
