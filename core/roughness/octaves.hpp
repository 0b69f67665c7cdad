// The noise octaves (internal to roughness/): white noise on rotated lattices
// of spacing 1 .. 32 cells, keyed on raster coordinates, interpolated with
// Catmull-Rom splines, added block by block where noise is wanted.
#pragma once

#include <cstdint>
#include <vector>

#include "roughness/amplitude.hpp"
#include "roughness/blocks.hpp"
#include "roughness/field.hpp"

namespace mcmd::rough {

constexpr int kOctaves = 6;         // spacings 1 .. 32 cells

// The noise, octave j weighted 2^(jH), times the amplitude, written to `out`
// (over area `a`) at the cells of `mask`, over the active blocks' noise boxes
// (the union of a run of neighbouring ones at a time; +0.0 at their other
// cells), block rows on `threads` threads (a lone field's noise, e.g. 3 %
// kept cells: each cell is written by one block row, the same bits for any
// count). Every mask cell must lie in its block's box.
void add_noise(const RoughField& g, const Area& a, const Blocks& blocks, const std::vector<std::uint8_t>& mask,
               std::uint64_t seed, double H, int octaves, const Amplitude& amplitude, std::vector<double>& out,
               int threads);

// The variance of the 5-point Laplacian of one octave of unit weight, as
// add_noise makes it (its samples interpolated), averaged over the cells:
// spacing 1 is white noise of unit variance (4² + 4 = 20); the others were
// measured over 6 × 4096² cells (spread between the 6 under 1 % up to spacing
// 16, 3 % at 32; Roughness.OctaveLaplacianVariancesHold checks them). The
// octaves are independent, so the noise's is the weighted sum: known without
// a pass over the noise.
constexpr double kOctaveLaplacianVariance[kOctaves] = {20.0, 1.628, 0.1216, 0.00866, 5.55e-4, 3.50e-5};
double noise_laplacian_variance(double H, int octaves);

// The octaves -rs auto makes: spacings 1, 2 and 4 (kAutoOctaves), and of
// those only the ones up to the field's depth, when its target cells all lie
// within `depth` cells of a constraint (< 0: not known; a coarser octave is
// smooth across every void of the field, and the conditioning takes it out
// again). The amplitude is calibrated on the Laplacian (calibration.hpp), a
// cell-scale measure the three finest octaves carry: the coarser ones only
// add bumps 8-32 cells wide that no rim predicts. Without them, on the
// accuracy benchmark, the blob voids' RMSE median goes 0.935 -> 0.881 of
// GDAL's (worst 1.30 -> 0.97), voids a quarter of the raster wide
// 1.109 -> 0.947, the Laplacian spread stays (blobs 1.006 -> 1.008), and the
// hillshades keep their grain (docs/default-method.md).
constexpr int kAutoOctaves = 3;
int auto_octaves(double depth);

}  // namespace mcmd::rough
