// The default method's fill of a void's field with its morphology: ridge and
// river lines (lines.hpp) and, with -morph auto, the channels routed through
// the void (channels.hpp). The smooth fill first, then the fill again with
// the line and channel cells as constraints (roughness included), the
// cross-profiles around the lines shaped, and the void's cells drained (no
// closed depression left in them).
#pragma once

#include <cstdint>
#include <vector>

#include "mcmd/params.hpp"
#include "mcmd/progress.hpp"
#include "morphology/lines.hpp"
#include "thin_plate/thin_plate.hpp"

namespace mcmd::morph {

// A line cell of the field (field index), with its height (NaN: the smooth
// fill's there) and, for a river cell whose height is the straight fall
// along its run, its place on the run: fill_with_morphology then takes the
// run's heights from its smooth fill instead (channel_heights).
struct FieldLineCell {
  std::int32_t cell = 0;
  CellState kind = CellState::river;
  double z = 0.0;
  RunPlace place;
};

// Half-width, in cells, of the band around a line whose cross-profile the
// default method shapes (shape_profiles).
constexpr int kProfileHalfWidth = 8;

// `field` as thin_plate_with_roughness takes it; `own` flags the void's
// cells (the routed and drained ones); `inflow` (null: no channels) the
// known terrain's accumulation draining into the void per cell; `lines` the
// line cells inside the field's voids. Pre: own and inflow hold w·h entries.
// Post: constraint cells unchanged; every unknown cell filled; with
// channels or river lines, no own cell in a closed depression of the field;
// routed channels only where keeps_channels.
void fill_with_morphology(const FieldView& field, long long x0, long long y0, const std::uint8_t* own,
                          const double* inflow, const std::vector<FieldLineCell>& lines, const FillParams& params,
                          const ThinPlateSchedule& schedule, const ProgressFn& progress = {});

// Drains z's own cells (drain, flow.hpp) and returns how much water they
// held in closed depressions: the sum of the raises (height × cells).
// Pre: z and own hold w·h cells.
double drain_held(double* z, int w, int h, const std::uint8_t* own);

// Whether fill_with_morphology keeps the fill with the routed channels: a
// channel must drain the void, not dig a basin (a path to a wrong outlet,
// pinned far below the smooth fill, can leave one, which the drain fills
// flat). Refused when that fill holds (drain_held) more than twice the
// water of the fill without them, plus a hundredth of the void's relief in
// `smooth` per own cell; the plain fill is kept then. Pre: smooth and own
// hold `cells` entries.
bool keeps_channels(double routed_held, double plain_held, const double* smooth, std::size_t cells,
                    const std::uint8_t* own);

// The cross-profiles within kProfileHalfWidth cells of the line cells, at
// the unknown cells of `state`: with u = d / kProfileHalfWidth (d: the
// distance to the nearest line cell, of height z_l), z ← z_l + (z − z_l)·φ(u),
// φ(u) = u^q for q >= 0 (q > 0: the cells near the line drawn towards it, a
// flat-floored valley or a rounded crest) and 2 − u^|q| for q < 0 (pushed
// away: a V valley or a sharp crest), q = I / 25 of the line's state
// (FillParams::river_shape, ridge_shape). Then within the band a river is
// the bottom and a ridge the top: a cell d cells away is kept at least
// step·d above a river (so that water runs along it, not beside it) and
// below a ridge. Pre: z, state hold w·h cells.
void shape_profiles(double* z, const CellState* state, int w, int h, const std::vector<FieldLineCell>& lines,
                    const FillParams& params, double step);

}  // namespace mcmd::morph
