// The drawn lines stay what they were drawn as after erosion: a river the
// way the water goes, a ridge the crest. Constraint cells never change;
// free cells beside them are moved the least that does it.
#pragma once

#include "mcmd/terrain.hpp"

namespace mcmd::terrain {

// Raise the free neighbours of each river cell that would take its water
// from the next river cell downstream (its steepest lower river
// neighbour): D8 from a river cell then follows the river.
void keep_rivers_draining(Canvas& c);

// Lower the free cells within kCrestReach cells of a ridge cell to below
// it: every ridge cell stays above the land beside it.
void keep_ridges_crests(Canvas& c);

constexpr int kCrestReach = 3;

}  // namespace mcmd::terrain
