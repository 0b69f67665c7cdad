// Flow routing on a w×h field (row-major): where water goes (D8 after
// Priority-Flood with ε, Barnes, Lehman & Mulla 2014) and how much of it.
// Deterministic: the same field gives the same flow, whatever ran before.
#pragma once

#include <bit>
#include <cstdint>
#include <limits>
#include <vector>

namespace mcmd::morph {

// The next double above a finite v: std::nextafter(v, +inf) without its
// library call (the ε of the flood; inline: called once per cell).
inline double next_above(double v) {
  if (v == 0.0) return std::numeric_limits<double>::denorm_min();
  const auto b = std::bit_cast<std::uint64_t>(v);
  return std::bit_cast<double>(v > 0 ? b + 1 : b - 1);
}

// What a cell is to the flow.
enum class FlowCell : std::uint8_t {
  off = 0,   // not part of it (nodata, or voids the analysis leaves out): an outlet beside it
  land = 1,  // water runs over it
  sink = 2,  // water that reaches it leaves the land (a void the known terrain drains into)
};

struct Flow {
  int w = 0, h = 0;
  // Per cell, the neighbour it drains to (D8): for a land cell beside a sink
  // the first such sink cell (east, then clockwise), else its steepest lower
  // land neighbour on the flooded levels (diagonals √2 away); -1 where water
  // leaves the field (a seed with no lower neighbour) and for off and sink
  // cells.
  std::vector<std::int32_t> receiver;
};

// Levels of Priority-Flood with ε over the land cells (Barnes, Lehman &
// Mulla 2014, with their queue for the cells it raises): every land cell
// gets max(its z, the next double above the level of the cell that reached
// it), so every land cell drains. Seeds (outlets): land cells on the
// field's border or beside an off or sink cell. Pre: z and kind hold w·h
// cells.
std::vector<double> flood_levels(const double* z, int w, int h, const FlowCell* kind);

// D8 flow on the flooded levels (Flow::receiver): every land cell drains.
// Sink cells' z is not read. Pre: as flood_levels.
Flow route(const double* z, int w, int h, const FlowCell* kind);

// Cells draining through each cell, itself included (1 for a land cell with
// nothing upstream); a sink cell holds what drains into it; off cells 0.
std::vector<double> accumulation(const Flow& flow, const FlowCell* kind);

// Raise the cells flagged in `raisable` that lie in closed depressions of z
// to their flooded level (Priority-Flood with ε over the box of the
// raisable cells, from its border one cell out), so that each drains to the
// box's border; every other cell keeps its value. Pre: z and raisable hold
// w·h cells.
void drain(double* z, int w, int h, const std::uint8_t* raisable);

}  // namespace mcmd::morph
