// Euclidean distance transform: how far each raster cell lies from the nearest
// valid cell. Used to honour a maximum fill distance (`-md`).
#pragma once

#include <cstdint>
#include <vector>

namespace mcmd {

// The maximum fill distance (-md, MAX_DISTANCE): a void cell is filled when
// max_distance is 0 (no limit) or its Euclidean distance, in cells, to the
// nearest known cell is at most max_distance. Every path of the raster
// engine decides with this.
inline bool within_fill_distance(double distance, double max_distance) {
  return max_distance <= 0 || distance <= max_distance;
}

// Distance, in cells, from every cell of a row-major w×h raster to the nearest
// cell with valid[i] != 0 (0 for valid cells). Exact, O(w·h) (Felzenszwalb &
// Huttenlocher 2012). Every distance is +infinity when no cell is valid.
// Pre: w, h >= 1, valid holds w·h flags.
std::vector<double> distance_to_valid(const std::uint8_t* valid, int w, int h);

// Per cell of the w×h raster, 1 when a valid cell lies within r along both
// axes at once (Chebyshev distance <= r: `valid` dilated by a (2r+1)² square),
// by sliding ORs along columns then rows. Pre: r >= 0, valid holds w·h flags.
std::vector<std::uint8_t> within_chebyshev(const std::uint8_t* valid, int w, int h, int r);

// Whether every cell of the w×h raster has a valid cell within r along both
// axes at once (Chebyshev distance <= r, so Euclidean <= r·√2): a cheap bound
// (within_chebyshev's byte passes) that spares the transform where every cell
// is near data, such as scattered samples. Pre: r >= 0, valid holds w·h flags.
bool all_within_chebyshev(const std::uint8_t* valid, int w, int h, int r);

}  // namespace mcmd
