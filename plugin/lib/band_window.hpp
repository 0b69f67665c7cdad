// Reading a window of a band into memory: elevations and which cells are valid.
// The unit a tiled pipeline streams (filled cells go back through BandAccess).
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "gdal_priv.h"
#include "lib/pixel_type.hpp"

namespace mcmd::gdal {

struct Window {
  int x = 0;
  int y = 0;
  int w = 0;
  int h = 0;
  std::size_t cells() const { return static_cast<std::size_t>(w) * static_cast<std::size_t>(h); }
};

struct WindowData {
  Window win;
  std::vector<double> z;            // elevations, row-major w×h
  std::vector<std::uint8_t> valid;  // 1 = valid (known), 0 = void
  bool voids_marked = false;        // a mask was given or a cell is not finite
  std::size_t void_count = 0;
};

// A window's values as the band holds them, kept from a read when asked for
// (a blank output copy is written from them: no second decode of the source).
struct NativeCells {
  std::shared_ptr<void> data;       // win.cells() values of `type`, row-major
  GDALDataType type = GDT_Unknown;  // GDT_Unknown: none kept (a type GDAL reads as Float64)
};

// Read `win` of `band`. A cell is void when it is not finite (NaN, ±inf) or
// any band of `masks` is 0 there. Callers leave out masks that mark nothing
// (a band's own mask with GMF_ALL_VALID).
// Throws Failure on I/O errors or when a mask's size differs from the band's.
// GDAL < 3.7 reads signed bytes (Byte + PIXELTYPE=SIGNEDBYTE) as 0..255 and its
// nodata mask ignores a negative nodata: with `signed_nodata`, such a band is
// read as int8 and its nodata cells are voids too.
WindowData read_window(GDALRasterBand& band, const PixelType& type, const std::vector<GDALRasterBand*>& masks,
                       const Window& win, bool signed_nodata);

// Throws Failure when `mask` is not the size of `band`.
void check_mask_size(GDALRasterBand& mask, GDALRasterBand& band);

// read_window into the caller's z and valid (win.cells() each); returns the
// void count, and whether voids are marked at all in *marked (may be null).
// With `keep`, the values as read in the band's own type are kept there.
std::size_t read_cells(GDALRasterBand& band, const PixelType& type, const std::vector<GDALRasterBand*>& masks,
                       const Window& win, bool signed_nodata, double* z, std::uint8_t* valid, bool* marked,
                       NativeCells* keep = nullptr);

}  // namespace mcmd::gdal
