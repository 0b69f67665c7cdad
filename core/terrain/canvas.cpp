#include <algorithm>
#include <stdexcept>
#include <string>

#include "mcmd/terrain.hpp"

namespace mcmd {

Canvas::Canvas(int width, int height) : w(width), h(height) {
  check_terrain_size(width, height);
  z.assign(cells(), 0.0);
  state.assign(cells(), CellState::unknown);
}

std::size_t Canvas::count(CellState s) const {
  return static_cast<std::size_t>(std::count(state.begin(), state.end(), s));
}

void Canvas::set(int x, int y, double elevation, CellState s) {
  const std::size_t i = index(x, y);
  z[i] = elevation;
  state[i] = s;
}

void check_terrain_size(long long w, long long h) {
  const std::string size = std::to_string(w) + "x" + std::to_string(h);
  if (w < 1 || h < 1) throw std::invalid_argument("the raster size " + size + " is not at least 1x1");
  if (w > static_cast<long long>(kMaxTerrainCells) || h > static_cast<long long>(kMaxTerrainCells) ||
      static_cast<unsigned long long>(w) * static_cast<unsigned long long>(h) > kMaxTerrainCells)
    throw std::invalid_argument("the raster size " + size + " is too large: at most " +
                                std::to_string(kMaxTerrainCells) + " cells (8192x8192) are made");
}

const char* method_name(TerrainMethod m) {
  switch (m) {
    case TerrainMethod::mcmd: return "mcmd";
    case TerrainMethod::paper: return "paper";
    case TerrainMethod::mdi: return "mdi";
    case TerrainMethod::none: return "none";
  }
  return "?";
}

const char* scheme_name(TerrainScheme s) {
  switch (s) {
    case TerrainScheme::diamond_square: return "ds";
    case TerrainScheme::triangle_edge: return "te";
    case TerrainScheme::butterfly: return "butterfly";
  }
  return "?";
}

}  // namespace mcmd

namespace mcmd {

double constraint_range(const Canvas& c) {
  double lo = 0.0, hi = 0.0;
  bool any = false;
  for (std::size_t i = 0; i < c.cells(); ++i) {
    if (!is_constraint(c.state[i])) continue;
    lo = any ? std::min(lo, c.z[i]) : c.z[i];
    hi = any ? std::max(hi, c.z[i]) : c.z[i];
    any = true;
  }
  return hi - lo;
}

}  // namespace mcmd
