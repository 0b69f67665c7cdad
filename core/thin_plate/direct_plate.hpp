// The thin plate of a field with only a few unknown cells, solved exactly:
// one dense Cholesky factorisation of the energy's Hessian over those
// cells. A raster's tiny voids (an SRTM tile holds hundreds of 1–20-cell
// voids) then cost a few microseconds each instead of a hierarchy, a
// cascade and conjugate gradients on a field of hundreds of cells.
//
// The energy is the solver's (thin_plate.hpp): Σ z_xx² + Σ z_yy² + 2 Σ z_xy²
// over the second differences whose cells lie in the field. The multigrid
// solve adds a pull towards its cascade of weight pull_length⁻⁴, negligible
// within a few cells of data, where every cell of such a void lies.
#pragma once

#include <cstddef>

#include "common/grid.hpp"

namespace mcmd {

// Fills the unknown cells of the w×h row-major field (z, state) with the
// exact thin plate through its constraint cells when there are at least one
// and at most `max_unknown` of them. Returns false, leaving the field
// untouched, when there are more or the plate is not unique there (no
// constraint close enough to hold it).
bool direct_thin_plate(int w, int h, double* z, const CellState* state, std::size_t max_unknown);

}  // namespace mcmd
