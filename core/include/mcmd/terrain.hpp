// Terrain synthesis, MCMD's second job (Belhadj 2007 §4): a raster made from
// scratch, around the constraints of a sketch, or around a skeleton of ridges
// and rivers (skeleton.hpp). The constraints are cells of a Canvas; every
// unknown cell is synthesised, constraint cells are never changed.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "mcmd/cell_state.hpp"
#include "mcmd/params.hpp"
#include "mcmd/progress.hpp"

namespace mcmd {

// A w×h raster of elevations and cell states, row-major, y growing downwards.
struct Canvas {
  int w = 0;
  int h = 0;
  std::vector<double> z;
  std::vector<CellState> state;

  Canvas() = default;
  Canvas(int width, int height);  // every cell unknown, elevation 0

  std::size_t cells() const { return static_cast<std::size_t>(w) * static_cast<std::size_t>(h); }
  std::size_t index(int x, int y) const { return static_cast<std::size_t>(y) * static_cast<std::size_t>(w) + x; }
  bool contains(int x, int y) const { return x >= 0 && y >= 0 && x < w && y < h; }
  std::size_t count(CellState s) const;
  std::size_t constraints() const { return cells() - count(CellState::unknown); }
  // Set a constraint cell.
  void set(int x, int y, double elevation, CellState s = CellState::known);
};

// Elevation range (max − min) of the constraint cells; 0 when there are none.
double constraint_range(const Canvas& canvas);

// The largest raster made (2^26 cells, e.g. 8192×8192): the default method
// needs about 120 bytes per cell.
constexpr std::size_t kMaxTerrainCells = std::size_t{1} << 26;

// Throws std::invalid_argument (one line naming the size) unless 1 <= w, h
// and w·h <= kMaxTerrainCells.
void check_terrain_size(long long w, long long h);

enum class TerrainMethod {
  mcmd,   // default: thin plate + fractal displacement, creased at ridges and rivers
  paper,  // the paper's MCMD (MDBU then MD) on TerrainParams::scheme
  mdi,    // the older bottom-up pass of Belhadj & Audibert 2005 (MDI), then plain MD
  none,   // no synthesis: the constraints alone
};

enum class TerrainScheme { diamond_square, triangle_edge, butterfly };

struct TerrainParams {
  TerrainMethod method = TerrainMethod::mcmd;
  TerrainScheme scheme = TerrainScheme::diamond_square;  // paper and mdi
  // Shapes (known, ridge, river), H, rt, rs, noise_unit, seed, Δ form; its
  // method field is not used. rs is a fraction of noise_unit, or of the
  // constraints' elevation range when noise_unit is 0.
  FillParams fill{};
  // mcmd: how sharp ridge crests and river valleys are, a factor of an
  // automatic cross-slope (0: the plain thin plate, smooth across them).
  double sharpness = 1.0;
  int threads = 1;  // the result does not depend on it
};

// Fill every unknown cell of `canvas` by `params.method` (none: nothing).
// params.fill.rs_auto (mcmd only): the relief's amplitude and H measured from
// the known cells (terrain/methods/measured_relief.hpp).
// Post: constraint cells and states unchanged, every elevation finite.
// Throws std::invalid_argument on bad parameters (a fractional rs with no
// elevation range to be a fraction of, rs auto with no known terrain to
// measure, nothing to make), Cancelled.
void synthesize(Canvas& canvas, const TerrainParams& params, const ProgressFn& progress = {});

// The names used in messages and options.
const char* method_name(TerrainMethod m);
const char* scheme_name(TerrainScheme s);

}  // namespace mcmd
