// A GDAL band pair seen by the core's tiled fill (mcmd::RasterAccess): cells
// are read from `source` (its values, NaN, nodata and the request's masks) and
// filled cells are written to `target`. When source and target are the same
// band (in place), a bitset of written cells (1 bit per cell) keeps later
// reads seeing those cells as void, as the tiled fill requires.
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include "fill_band.hpp"
#include "gdal_priv.h"
#include "mcmd/tiled_fill.hpp"
#include "pixel_type.hpp"

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

  // Whether the nodata value marks voids (besides NaN and masks).
  bool nodata_marks_voids() const;

 private:
  void read(int x0, int y0, int w, int h, double* z, std::uint8_t* valid);
  void write(int x0, int y0, int w, int h, const double* z, const std::uint8_t* mask);
  bool was_written(std::size_t cell) const { return (written_[cell >> 6] >> (cell & 63)) & 1u; }

  GDALRasterBand& target();

  GDALRasterBand& source_;
  TargetBand get_target_;
  GDALRasterBand* target_ = nullptr;  // once asked for
  const FillRequest& request_;
  PixelType source_type_;
  PixelType target_type_;
  bool in_place_;
  std::vector<std::uint64_t> written_;  // in place only
  std::vector<unsigned char> run_;
};

}  // namespace mcmd::gdal
