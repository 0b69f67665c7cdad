// A GDAL band pair seen by the core's tiled fill (mcmd::RasterAccess): cells
// are read from `source` (its values, NaN, nodata and the request's masks) and
// filled cells are written to `target`. When source and target are the same
// band (in place), a bitset of written cells (1 bit per cell) keeps later
// reads seeing those cells as void, as the tiled fill requires. A blank target
// (request.blank_target) gets every cell: a whole-band write puts the filled
// cells over the source's as read, and complete() copies whatever cell was
// not written from the source.
#pragma once

#include <algorithm>
#include <bit>
#include <cstdint>
#include <functional>
#include <vector>

#include "gdal_priv.h"
#include "lib/band_window.hpp"
#include "lib/fill_request.hpp"
#include "lib/pixel_type.hpp"
#include "mcmd/fill_raster.hpp"

namespace mcmd::gdal {

class BandAccess {
 public:
  // Throws Failure for a mask whose size differs from the band's.
  BandAccess(GDALRasterBand& source, GDALRasterBand& target, const FillRequest& request);
  // A target that may not exist yet (a copy still being made): asked for at
  // the first write, never the source itself.
  BandAccess(GDALRasterBand& source, TargetBand target, const FillRequest& request);
  BandAccess(const BandAccess&) = delete;
  BandAccess& operator=(const BandAccess&) = delete;

  // Valid while this object lives. read/write throw Failure on I/O errors.
  RasterAccess access();

  GDALDataType source_type() const { return source_.GetRasterDataType(); }
  // The source band's dataset (its georeferencing), or null.
  GDALDataset* source_dataset() const { return source_.GetDataset(); }
  // Whether the target is the source itself (a fill in place).
  bool in_place() const { return in_place_; }

  // Whether the nodata value marks voids (besides NaN and masks).
  bool nodata_marks_voids() const;

  // After a successful fill: a blank target's cells that the fill did not
  // write are copied from the source, so that the target holds every cell.
  // Throws Failure on I/O errors.
  void complete();

 private:
  void read(int x0, int y0, int w, int h, double* z, std::uint8_t* valid);
  void write(int x0, int y0, int w, int h, const double* z, const std::uint8_t* mask);
  void write_over_kept(const double* z, const std::uint8_t* mask);
  void complete_rows(int y0, int rows);
  bool was_written(std::size_t cell) const { return (written_[cell >> 6] >> (cell & 63)) & 1u; }
  // fn(k) for the written cells first + k, k < n, in order: a word of 64
  // cells at a time (most hold no written cell).
  template <class Fn>
  void for_each_written(std::size_t first, std::size_t n, Fn fn) const {
    for (std::size_t k = 0; k < n;) {
      const std::size_t cell = first + k, bit = cell & 63;
      const std::size_t take = std::min<std::size_t>(64 - bit, n - k);
      std::uint64_t word = written_[cell >> 6] >> bit;
      if (take < 64) word &= (std::uint64_t{1} << take) - 1;
      for (; word; word &= word - 1) fn(k + static_cast<std::size_t>(std::countr_zero(word)));
      k += take;
    }
  }
  void mark_written(std::size_t cell) { written_[cell >> 6] |= std::uint64_t{1} << (cell & 63); }
  bool whole(int x0, int y0, int w, int h) const {
    return x0 == 0 && y0 == 0 && w == source_.GetXSize() && h == source_.GetYSize();
  }

  GDALRasterBand& target();

  GDALRasterBand& source_;
  TargetBand get_target_;
  GDALRasterBand* target_ = nullptr;  // once asked for
  const FillRequest& request_;
  PixelType source_type_;
  PixelType target_type_;
  bool in_place_;
  std::vector<std::uint64_t> written_;  // in place, or a blank target
  NativeCells kept_;                    // a blank target's source cells, from a whole-band read
  std::vector<unsigned char> run_;
};

}  // namespace mcmd::gdal
