// Channels through a void (-morph auto): where the known terrain's drainage
// enters a void component, where it leaves, the path between, and the
// heights along it. The fill then takes the path as river cells, so a
// valley that enters a void continues through it instead of being dammed.
#pragma once

#include <cstdint>
#include <vector>

#include "mcmd/cell_state.hpp"

namespace mcmd::morph {

struct ChannelField {
  int w = 0, h = 0;            // a field of the raster, row-major
  const double* z = nullptr;   // the constraints' values, and the smooth fill at unknown cells
  const CellState* state = nullptr;
  const std::uint8_t* own = nullptr;  // the void component routed through (unknown cells)
  // Per cell: the known terrain's accumulation (cells) of a constraint cell
  // that drains into the component, 0 elsewhere (flow.hpp, voids as sinks).
  const double* inflow = nullptr;
};

// The known terrain's drainage with every void as a sink: per cell, the
// accumulation (cells) of a known cell that drains into a void, 0 at other
// cells. The ChannelField::inflow of a raster. Pre: z, valid hold w·h cells.
std::vector<double> inflow_into_voids(const double* z, const std::uint8_t* valid, int w, int h);

// The heights of a channel's cells between its two fixed ends: fill[0] is
// the top's height, fill.back() the bottom's, fill between them the smooth
// fill's at the cells, `along` their lengths from the top. Each height is
// the mean of a fall that leaves the top between the fill's slope and the
// straight fall's and arrives at the straight fall's, and the least-squares
// non-increasing fit of the fill (which keeps the fill's shape where it
// already descends and levels a dam where it does not).
// Pre: fill.size() == along.size() >= 2, fill[0] > fill.back(), along
// increasing from 0. Post: the ends unchanged; non-increasing, within them.
std::vector<double> channel_heights(const std::vector<double>& fill, const std::vector<double>& along);

struct RiverCell {
  std::int32_t cell = 0;  // field index
  double z = 0.0;
};

// Every inflow of at least min_inflow cells, largest first, is routed to
// its outlet: where the smooth fill's own drainage leaves the component, if
// that is lower than the inflow, else the lowest cell of the component's
// rim (the spill point of a lake there). The path is the least-cost path
// through the component's cells, a step costing
// exp(8·(fill − lowest)/(fill's range)) (it keeps to the fill's valley
// floor), and it ends where it meets a path already routed or a river cell
// of the field (a line the user gave: a tributary joins; the line keeps its
// heights). Its heights fall from the inflow's to the outlet's (or the
// junction's): channel_heights of the fill along the path.
// Post: cells are own cells, each once, heights finite; empty when no
// inflow reaches min_inflow.
std::vector<RiverCell> route_channels(const ChannelField& f, double min_inflow);

}  // namespace mcmd::morph
