// The one entry point of the core: fill the unknown cells of a grid.
#pragma once

#include <cstdint>
#include <span>

#include "mcmd/delta.hpp"
#include "mcmd/grid.hpp"
#include "mcmd/progress.hpp"
#include "mcmd/subdivision.hpp"

namespace mcmd {

enum class Method {
  mcmd,      // default: MCMD's bottom-up/top-down structure with better ingredients
  paper_ds,  // the paper, diamond-square
  paper_te,  // the paper, triangle-edge
};

// Shape parameters of one cell state (paper §4.3: ridge and river cells carry
// their own I and I_bu).
struct StateShape {
  double I = 0.0;     // top-down (MD) interpolation shape
  double I_bu = 0.0;  // bottom-up (MDBU) interpolation shape
};

struct FillParams {
  Method method = Method::mcmd;
  DeltaForm delta_form = DeltaForm::normalized;
  StateShape known_shape{};  // known cells, and cells computed by the fill
  StateShape ridge_shape{};
  StateShape river_shape{};
  double H = 0.5;   // Hurst-like exponent of the displacement
  double rt = 0.0;  // translation of the uniform deviate
  double rs = 0.0;  // displacement scale, a fraction of noise_unit; 0 = smooth
  bool rs_auto = false;      // calibrate amplitude and H from the known terrain
  double noise_unit = 0.0;   // elevation unit of rs; 0 = known elevation range of the grid
  double dmax = 0.0;         // Δ's d_max; 0 = the grid's diagonal
  std::uint64_t seed = 0;
};

// The shape parameters that apply to a cell of state `s`.
const StateShape& shape_for(const FillParams& params, CellState s);

// The scheme a paper method uses. Pre: method is paper_ds or paper_te.
Scheme scheme_of(Method method);

// Whether the default method adds roughness (-rs auto, or -rs > 0) to its
// smooth fill (roughness.hpp).
inline bool adds_roughness(const FillParams& p) { return p.rs_auto || p.rs > 0; }

// Fill every unknown cell of `grid` with `params.method`.
// Pre: at least one cell is a constraint (known, ridge or river); parameters finite.
// Post: every elevation is finite; constraint cells and all states are unchanged.
// Throws Cancelled when `progress` refuses, std::invalid_argument on bad input.
void fill(Grid& grid, const FillParams& params, const ProgressFn& progress = {});

// Elevation range (max - min) over the constraint cells; 0 when there are none.
// Pre: z and states have one entry per cell.
double known_range(std::span<const double> z, std::span<const CellState> states);
double known_range(const Grid& grid);

}  // namespace mcmd
