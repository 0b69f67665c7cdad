// The coarse guide: one small fill of the whole raster that makes the upper
// levels of the subdivision consistent between tiles (docs/tiling.md).
//
// Lattice point (i, j) sits at raster cell (i·S, j·S), S a power of two. It
// is known when the S×S block around it ([i·S - S/2, i·S - S/2 + S) in each
// axis) has a known cell, and holds the value at the lattice point of a least-
// squares plane through the block's known cells (slightly regularised; one
// cell gives its value): unlike a plain mean it is not biased towards the
// known side of a block that a void cuts. The lattice has
// ceil((W - 1) / S) + 1 points per row (at most max_side), the last one on or
// past the raster's last cell; it is filled once as it is (the default
// method: a w×h field) or mirror-padded to a 2^m+1 grid for mcmd::fill (the
// paper methods, tension); windows then read it through an
// interpolating bicubic (Catmull-Rom) at full resolution.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "common/grid.hpp"
#include "mcmd/params.hpp"
#include "mcmd/progress.hpp"
#include "raster/tiles/tile_layout.hpp"

namespace mcmd {

// Smallest power of two S with ceil((max(w, h) - 1) / S) + 1 <= max_side.
int guide_stride(int width, int height, int max_side = 1025);

// Unknown cells farther than this many strides from data are pinned to the
// guide (measured: 4 and 16 were worse on blob voids; docs/tiling.md).
constexpr double kGuideRadiusStrides = 8.0;

// A void whose farthest cell lies more than 128 cells from data reaches far:
// deep inside it the guide's surface takes over, under tension, and the
// small-raster path leaves the raster to tiles (docs/tiling.md).
bool reaches_far(double farthest);

// How much of the guide's tensioned surface a void whose farthest cell lies
// `farthest` raster cells from data takes: 0 up to 32 cells, ramping to 1
// at 96 (docs/tiling.md, the coarse guide); a weight below 1 % is 0.
double far_void_weight(double farthest);

// Lattice points [x0, x1) × [y0, y1).
struct LatticeBox {
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
};

class CoarseGuide {
 public:
  CoarseGuide() = default;
  // Pre: width, height >= 1, stride a power of two.
  CoarseGuide(int width, int height, int stride);

  // Accumulate raster rows [y0, y0 + rows), full width, row-major
  // (valid[i] != 0: known). Rows may come in any order, each once (in
  // raster order for the same bits whatever the chunks).
  void add_rows(int y0, int rows, const double* z, const std::uint8_t* valid);

  // Sums of a block's known cells, offsets from its lattice point.
  struct Moments {
    double n = 0, z = 0, x = 0, y = 0, xx = 0, yy = 0, xy = 0, zx = 0, zy = 0;
  };
  // A rectangle of raster cells, row-major (valid[i] != 0: known).
  struct CellBlock {
    int x0 = 0, y0 = 0, w = 0, h = 0;
    const double* z = nullptr;
    const std::uint8_t* valid = nullptr;
  };

  // The guide built in parts (a fill split over workers, mcmd/chunked_fill.hpp):
  // the lattice points whose raster coordinate i·S lies in [begin, end) along
  // an axis of `length` cells; the moments of lattice points is × js from
  // cells that hold all of their blocks' cells (else std::invalid_argument),
  // row-major, summed exactly as add_rows sums them; and set into the guide.
  static Range lattice_points(int length, int stride, int begin, int end);
  static std::vector<Moments> part_moments(int width, int height, int stride, Range is, Range js,
                                           const CellBlock& cells);
  void set_moments(Range is, Range js, const std::vector<Moments>& part);

  // Fill the lattice (same method as the windows). Returns false, and stays
  // unusable, when no lattice point is known. Throws Cancelled. With
  // threads > 1 the plain and the tensioned surfaces (when a void needs
  // both) are solved at the same time; the result is the same.
  bool solve(const FillParams& params, const ProgressFn& progress = {}, int threads = 1);

  bool ready() const { return ready_; }
  int stride() const { return stride_; }
  int lattice_width() const { return cw_; }
  int lattice_height() const { return ch_; }

  // The guide surface at raster cell (x, y); cells outside are reflected in.
  // Exact lattice value at lattice points. Pre: ready().
  double at(long long x, long long y) const;

  // Distance (cells) from raster cell (x, y) to the nearest known cell,
  // estimated on the lattice: S × the distance from the nearest lattice point
  // to the nearest lattice point whose block holds a known cell; within about
  // 1.5·S of the exact value. For max distances beyond what a window sees.
  // Pre: ready(); prepare_distance() called once before (not thread-safe).
  void prepare_distance();
  double coarse_distance(long long x, long long y) const;

 private:
  // `start` (cw × ch, known points set) filled by the method of `params`,
  // the solver on `threads` threads (the same bits for any).
  std::vector<double> filled(const std::vector<double>& start, const FillParams& params, const ProgressFn& progress,
                             int threads) const;
  // The voids of the lattice (8-connected unknown points) that take some of
  // the tensioned surface: per point its far_void_weight (0 at known points
  // and in other voids) and its void's index, -1 outside them; per void its
  // box. Distances measured on the lattice.
  struct FarVoids {
    std::vector<double> weight;
    std::vector<int> label;
    std::vector<LatticeBox> boxes;
  };
  FarVoids far_voids() const;
  // `mean` with each far void's points filled under `tension`: the surface
  // of the mirror-padded lattice, solved in a square around each void (the
  // same bits for any thread count).
  std::vector<double> tense_filled(const std::vector<double>& mean, const FarVoids& far, double tension,
                                   const FillParams& params, const ProgressFn& progress, int threads) const;
  // Sets value_ to the plain fill of `mean` and returns tense_filled: side
  // by side on two threads for a small lattice, one after the other on
  // `threads` threads each for a large one (`unknown` points).
  std::vector<double> plain_and_tense(const std::vector<double>& mean, const FarVoids& far, std::size_t unknown,
                                      const FillParams& params, const ProgressFn& progress, int threads);
  // Point i's value from its block's sums (m.n > 0: known).
  void set_point(std::size_t i, const Moments& m);
  // Lattice row j's values from its open sums, which are freed.
  void close_row(int j);
  int width_ = 1, height_ = 1, stride_ = 1, cw_ = 1, ch_ = 1;
  // The sums of the blocks of a lattice row are kept only while its raster
  // rows arrive (a 601² lattice's for every point held 26 MB, faulted in
  // before the first pass: 4-65 ms on the 4801² mosaic).
  std::vector<std::vector<Moments>> open_;
  std::vector<int> rows_left_;  // per lattice row: raster rows still to come
  std::vector<double> mean_;    // per point: its block's plane value, until solve
  std::vector<double> value_;        // cw × ch after solve
  std::vector<std::uint8_t> known_;  // lattice points whose block holds a known cell
  std::vector<double> distance_;     // lattice distance to a known point (prepare_distance)
  bool ready_ = false;
};

}  // namespace mcmd
