// A sketch (any raster GDAL reads: a grey PNG from an image editor, a DEM)
// as the constraints of a terrain: its unknown cells by the UNKNOWN rule,
// its grey levels mapped to elevations by ZRANGE; and the STATES raster
// that makes some of them ridge or river cells.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "gdal_priv.h"
#include "lib/terrain_options.hpp"
#include "mcmd/terrain.hpp"

namespace mcmd::gdal {

struct SketchCells {
  int w = 0, h = 0;
  std::vector<double> z;            // elevations (after ZRANGE)
  std::vector<std::uint8_t> valid;  // 1 = a constraint
};

// Throws Failure (I/O, a rule the band's type cannot follow).
SketchCells read_sketch(GDALRasterBand& band, const TerrainOptions& options);

// The cells as a canvas of known cells (upsampled when options.upsample > 1).
Canvas sketch_canvas(const SketchCells& cells, int upsample);

// The states raster `path` (the canvas's size): in a one-band raster 1 marks
// a ridge cell, 2 a river cell; in a colour image red pixels mark ridges and
// blue ones rivers (painted on a layer of the sketch). A mark applies to a
// constraint cell only. Throws Failure (cannot open, wrong size).
void apply_states(Canvas& canvas, const std::string& path);

}  // namespace mcmd::gdal
