// The parameters of a fill: which method, the shape of each cell state, the
// roughness. A leaf header: every layer of the core and the plugin read it.
#pragma once

#include <cstddef>
#include <cstdint>

#include "mcmd/cell_state.hpp"

namespace mcmd {

enum class Method {
  mcmd,      // default: MCMD's bottom-up/top-down structure with better ingredients
  paper_ds,  // the paper, diamond-square
  paper_te,  // the paper, triangle-edge
};

// How the paper's Δ combines parent contributions (paper/delta.hpp).
enum class DeltaForm {
  normalized,  // Σ e·w / Σ w : translation-invariant (fill(z+c) = fill(z)+c); default
  paper,       // Σ e·w / count : the paper's average, pulls values toward 0 when I != 0
};

// Shape parameters of one cell state (paper §4.3: ridge and river cells carry
// their own I and I_bu).
struct StateShape {
  double I = 0.0;     // top-down (MD) interpolation shape
  double I_bu = 0.0;  // bottom-up (MDBU) interpolation shape
};

// Morphology of the fill (-morph auto): the known terrain's drainage routed
// through the voids as river cells (core/morphology/channels.hpp).
struct MorphParams {
  bool channels = false;
  // Cells of known terrain draining into a void that make a channel there;
  // 0: default_channel_cells.
  double min_inflow = 0.0;
};

// 0.1 % of the raster's known cells, at most 2000: the inflows routed on the
// hydrology benchmark (bench/HYDROLOGY.md), and channels at the scale of a
// void however large the raster.
inline double default_channel_cells(std::size_t known_cells) {
  const double c = 0.001 * static_cast<double>(known_cells);
  return c < 2000.0 ? c : 2000.0;
}

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
  MorphParams morph{};
  // The resolution of the output (1 for integer bands; 0: continuous): a
  // drop smaller than it would be rounded away (morphology's river banks).
  double z_step = 0.0;
};

// The shape parameters that apply to a cell of state `s`.
inline const StateShape& shape_for(const FillParams& params, CellState s) {
  switch (s) {
    case CellState::ridge: return params.ridge_shape;
    case CellState::river: return params.river_shape;
    default: return params.known_shape;
  }
}

// Whether the default method adds roughness (-rs auto, or -rs > 0) to its
// smooth fill (roughness/roughness.hpp).
inline bool adds_roughness(const FillParams& p) { return p.rs_auto || p.rs > 0; }

}  // namespace mcmd
