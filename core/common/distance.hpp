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

// distance_to_valid over a part of the raster, for callers that only ask
// whether cells of a rectangle lie within `reach` of a valid cell: `part` is
// the rectangle [x0, x1) × [y0, y1) grown by ceil(reach) + 1 cells, clipped.
// At a cell of the rectangle the distance is exact when the true one is at
// most `reach` (that valid cell lies in the part) and above `reach`
// otherwise (the part holds no valid cell the raster lacks). A small
// rectangle in a large raster then costs what the part costs.
struct PartDistance {
  int x0 = 0, y0 = 0, w = 0, h = 0;  // the part
  std::vector<double> d;              // w·h, row-major
  bool empty() const { return d.empty(); }
  double at(int x, int y) const { return d[static_cast<std::size_t>(y - y0) * w + (x - x0)]; }
};
// The part's margin around the rectangle for `reach`: ceil(reach) + 1.
int near_margin(double reach);
// Pre: the rectangle lies in the raster, reach >= 0.
PartDistance distance_to_valid_near(const std::uint8_t* valid, int w, int h, int x0, int y0, int x1, int y1,
                                    double reach);

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
