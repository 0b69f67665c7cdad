// Natural roughness for the default method: a fractal correction added to the
// smooth thin-plate fill, zero at the constraint cells and growing smoothly
// into the voids (a conditional simulation with the thin plate as the
// interpolator).
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "mcmd/fill.hpp"

namespace mcmd {

// The noise's octaves (unweighted: H is estimated per field) on the 32² blocks
// of one raster, each block computed once, by the first field that needs it,
// and shared by the others: the fields of a small raster overlap (on the
// 1201² blob benchmark they covered their noise blocks 2.3 times, 5.3 on
// Zion), and the octaves were a third of a -rs auto run. Thread-safe; the
// values are the ones a field computes alone, bit for bit.
class NoiseOctaves {
 public:
  NoiseOctaves(long long width, long long height, std::uint64_t seed);
  ~NoiseOctaves();
  NoiseOctaves(const NoiseOctaves&) = delete;
  NoiseOctaves& operator=(const NoiseOctaves&) = delete;
  std::uint64_t seed() const { return seed_; }
  // Block (bi, bj), raster cells [32·bi, 32·bi + 32) × [32·bj, 32·bj + 32)
  // (those inside the raster): octave j's value at cell (x, y) of the block is
  // at [j·32² + 32·(y − 32·bj) + (x − 32·bi)].
  const double* block(long long bi, long long bj) const;

 private:
  struct Slot;
  long long width_, height_, nbx_, nby_;
  std::uint64_t seed_;
  std::unique_ptr<Slot[]> slots_;
};

// A w×h part of a raster (row-major) whose cell (0, 0) is raster cell (x0, y0):
// the noise is keyed on raster coordinates, so any window or field of a
// raster sees the same noise. Unknown cells are the non-constraint ones.
struct RoughField {
  int w = 0, h = 0;
  long long x0 = 0, y0 = 0;
  double* z = nullptr;                // written by add_roughness only
  const CellState* state = nullptr;
  const NoiseOctaves* octaves = nullptr;  // the raster's shared octaves (x0, y0 >= 0), or computed here
  std::size_t cells() const { return static_cast<std::size_t>(w) * static_cast<std::size_t>(h); }
  std::size_t index(int x, int y) const { return static_cast<std::size_t>(y) * static_cast<std::size_t>(w) + x; }
  bool contains(int x, int y) const { return x >= 0 && y >= 0 && x < w && y < h; }
  double z_at(int x, int y) const { return z[index(x, y)]; }
  CellState state_at(int x, int y) const { return state[index(x, y)]; }
  // A grid as a field (read-only use when the grid is const).
  static RoughField of(const Grid& g) {
    return RoughField{g.side(), g.side(), g.origin_x(), g.origin_y(), const_cast<double*>(g.elevations().data()),
                      g.states().data()};
  }
};

// Terrain statistics from the constraint cells: semivariogram γ(d) over
// horizontal and vertical pairs of constraint cells at lags 1, 2, 4, 8, 16.
struct RoughnessModel {
  double H = 0.5;         // Hurst exponent, from the slope of log γ against log d
  double curvature = 0.0; // variance of a second difference: 8γ(1) - 2γ(2) from many lag-1
                          // pairs, a calibrated fBm form γ(1)(8 - 2·4^H) from few (scattered samples)
  bool valid = false;     // enough pairs to estimate
};
RoughnessModel estimate_roughness(const Grid& grid);
RoughnessModel estimate_roughness(const RoughField& field);

// Unconditioned fractal noise at every cell: octaves of spacing 2^j
// (j = 0 .. octaves-1), each white noise on a lattice rotated by j golden
// angles and interpolated with Catmull-Rom splines (smooth, no axis-aligned
// blocks), weighted 2^(jH). Keyed on (seed, global coordinates): any window of
// a raster sees the same noise.
std::vector<double> fractal_noise(const Grid& grid, std::uint64_t seed, double H, int octaves);

// Add roughness to the unknown cells of `grid`, which hold the smooth fill.
// The noise is generated only in 32² blocks (aligned to global coordinates)
// near voids and conditioned on the constraints. rs_auto: H from
// estimate_roughness; the amplitude per block makes the 5-point Laplacian
// variance of fill + noise over the block's voids (and its neighbours') equal
// to the terrain's around it (directional semivariogram of the nearest
// constraint pairs, through a summed-area table), blending into a global
// target from estimate_roughness's curvature where too few pairs lie within
// 4 blocks. Else rs > 0: amplitude
// rs · noise_unit for the coarsest octave, H = params.H. No-op otherwise.
void add_roughness(Grid& grid, const FillParams& params);
// The same on a field of any size (single_field.cpp's voids); `threads` run
// the conditioning solve of a large field (same result for any count).
void add_roughness(const RoughField& field, const FillParams& params, int threads = 1);

}  // namespace mcmd
