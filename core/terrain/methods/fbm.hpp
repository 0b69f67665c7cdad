// Fractional Brownian relief over a whole raster, the displacement of a
// terrain made from scratch or around sparse constraints: the roughness
// layer's octaves (white noise on rotated lattices of spacing 2^j, Catmull-Rom
// splines, keyed on raster coordinates: no axis-aligned artefact, the same
// bits for any thread count), from spacing 1 up to about half the raster.
#pragma once

#include <cstdint>
#include <vector>

namespace mcmd::terrain {

// Octaves a w×h raster gets: spacings 1 .. 2^(n-1) <= max(w, h) / 2, n >= 1.
int fbm_octaves(int w, int h);

// The first `octaves` octaves, octave j weighted 2^(jH) and the whole scaled
// so that the coarsest octave of `scale_octaves` has amplitude `amplitude`
// (its nodes have unit variance). Row-major w×h.
std::vector<double> fbm_relief(int w, int h, std::uint64_t seed, double H, double amplitude, int octaves,
                               int scale_octaves, int threads);

}  // namespace mcmd::terrain
