// Where the water of an eroding terrain goes, recomputed each time step.
// Water runs on `level`: the heights, raised where they would hold water
// (sediment fills the lakes), so that every cell but the border's has a
// lower neighbour. Each cell sends its water down its steepest descent
// (D8, the receiver the stream power erodes towards) and spreads its
// drainage area over all of its lower neighbours (multiple flow
// directions: hillslopes do not streak along the grid). The raster's
// border drains out. The drawn lines guide the water (WaterGuides): a
// ridge's cells take no water while a cell has another lower neighbour, so
// that the land drains away from them on both sides and they stay divides;
// a river's cells bring water of their own, so that they carve the valley
// they run in.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

namespace mcmd::terrain {

// What the drawn lines ask of the water (an empty vector: nothing).
struct WaterGuides {
  std::vector<std::uint8_t> divide;  // w·h: cells no water enters while it can go elsewhere (ridges)
  std::vector<double> source;        // w·h: drainage area a cell brings besides its own, in its grid's cells (rivers)
};

// The 8 directions are d8's (common/d8.hpp): clockwise from the east.
constexpr std::uint8_t kOutlet = 8;  // Drainage::to of a border cell: its water leaves the raster

struct Drainage {
  int w = 0, h = 0;
  std::array<std::int32_t, 8> offset{};  // index offsets of the directions
  std::vector<double> level;             // the surface the water runs on
  std::vector<std::uint8_t> to;          // direction of the steepest lower neighbour, kOutlet on the border
  std::vector<std::uint8_t> lower;       // bit k: the water goes to the neighbour in direction k
  std::vector<std::int32_t> order;       // every cell after all of its lower neighbours
  std::vector<float> area;               // cells draining through each (itself included)

  // The cell receiving i's water (D8), -1 on the border.
  std::int32_t receiver(std::int32_t i) const { return to[i] == kOutlet ? -1 : i + offset[to[i]]; }
};

// Scratch reused from step to step.
struct DrainageScratch {
  std::vector<std::uint8_t> count;
  std::vector<std::int32_t> stack;
};

// Fill every depression of z (morph::flood_levels, Priority-Flood with ε
// from the border: each cell ends strictly above the cell that reached it)
// into d.level, raise the free cells of z to it (a fixed cell keeps its
// height, water passes over it), then route(). Pre: z finite, w, h >= 3.
void flood(std::vector<double>& z, const std::vector<std::uint8_t>& fixed, const WaterGuides& guides, int w, int h,
           Drainage& d, DrainageScratch& scratch);

// After a step moved z a little: raise the cells that sank to or below
// their last receiver (which was lower) just above it, outlets first, as
// flood() would (cheaply: along last step's network), then route().
// Pre: d holds last step's drainage of these w×h cells.
void keep_draining(std::vector<double>& z, const std::vector<std::uint8_t>& fixed, const WaterGuides& guides,
                   Drainage& d, DrainageScratch& scratch);

}  // namespace mcmd::terrain
