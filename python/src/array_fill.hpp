// Filling a raster held in memory (a numpy array's buffer) with the GDAL
// glue's own band fill (lib/fill_band.hpp): the buffer is a band of an
// in-memory GDAL dataset (MEM, no copy), so voids, nodata, masks and the
// encoding of filled cells (lib/pixel_type.hpp's encode) are the CLI's.
#pragma once

#include <cstdint>
#include <variant>

#include "cli/dataset.hpp"
#include "gdal.h"
#include "lib/fill_request.hpp"
#include "lib/options.hpp"
#include "mcmd/progress.hpp"

namespace mcmd::python {

// A band's nodata value: none, a double, or a 64-bit integer for (U)Int64.
using Nodata = std::variant<std::monostate, double, std::int64_t, std::uint64_t>;

struct MemoryRaster {
  void* cells = nullptr;  // width × height values of `type`, row-major, native byte order
  GDALDataType type = GDT_Unknown;
  bool signed_byte = false;  // int8 held as GDT_Byte (GDAL < 3.7 has no GDT_Int8)
  int width = 0;
  int height = 0;
};

// The GDAL type of a numpy dtype named as GDAL names it ("Int16"; "Int8"
// maps to a signed GDT_Byte before GDAL 3.7). Throws std::invalid_argument.
MemoryRaster memory_raster(const char* gdal_type_name, void* cells, int width, int height);

// `raster` as band 1 of a MEM dataset over its cells (not copied), with its
// nodata value and `valid` (width × height bytes, may be null; 0 = void) as a
// mask: the band and the request the CLI would fill. With `filled` (width ×
// height bytes, may be null), every cell the fill writes is set to 1 there:
// what tells a void left unfilled from one filled with its old value.
// Flushes when destroyed.
class MemoryBand {
 public:
  MemoryBand(const MemoryRaster& raster, const std::uint8_t* valid, const Nodata& nodata,
             std::uint8_t* filled = nullptr);
  ~MemoryBand();
  MemoryBand(const MemoryBand&) = delete;
  MemoryBand& operator=(const MemoryBand&) = delete;
  GDALRasterBand& band() { return *band_; }
  const gdal::FillRequest& request() const { return request_; }

 private:
  cli::DatasetPtr ds_, mask_ds_;
  GDALRasterBand* band_ = nullptr;
  gdal::FillRequest request_;
};

// Fill the voids of `raster` in place: NaN and infinite cells, cells equal to
// `nodata`, and cells where `valid` (width × height bytes, may be null) is 0;
// `filled` (may be null) as for MemoryBand.
// Throws what gdal::fill_band throws (Failure, Cancelled, OptionError...).
void fill_memory_raster(const MemoryRaster& raster, const std::uint8_t* valid, const Nodata& nodata,
                        const gdal::Options& options, const ProgressFn& progress, std::uint8_t* filled = nullptr);

}  // namespace mcmd::python
