// Helpers for the mcmd_terrain tests: run the real binary, write rasters of
// given values (GeoTIFF, PNG), read them back.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "gdal_priv.h"
#include "test_support.hpp"

namespace mcmd::test {

// Run build/bin/mcmd_terrain with `args`.
RunResult run_terrain(const std::vector<std::string>& args);

struct Image {
  int w = 0, h = 0, bands = 1;
  GDALDataType type = GDT_Byte;
  std::vector<double> values;  // band after band, row-major
  double at(int x, int y, int band = 0) const { return values[(static_cast<std::size_t>(band) * h + y) * w + x]; }
};

// Write `img` with driver "PNG" or "GTiff"; GTiff gets `epsg` and `transform` when given.
void write_image(const std::string& path, const Image& img, const char* driver, int epsg = 0,
                 const std::array<double, 6>* transform = nullptr, const double* nodata = nullptr);

// Band `band` (1-based) of a raster.
Image read_image(const std::string& path, int band = 1);

// The test sketch of sketch_fixture.hpp at n×n: a UInt16 PNG of grey levels
// z·10 (white elsewhere) and an RGB PNG marking its ridges red, its river blue.
void write_test_sketch(const std::string& sketch, const std::string& states, int n);

}  // namespace mcmd::test
