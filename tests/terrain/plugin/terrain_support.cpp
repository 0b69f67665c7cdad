#include "terrain_support.hpp"

#include <cmath>
#include <memory>
#include <stdexcept>

#include "ogr_spatialref.h"
#include "sketch_fixture.hpp"

namespace mcmd::test {

namespace {

struct Closer {
  void operator()(GDALDataset* ds) const { GDALClose(GDALDataset::ToHandle(ds)); }
};
using Ds = std::unique_ptr<GDALDataset, Closer>;

}  // namespace

RunResult run_terrain(const std::vector<std::string>& args) {
  // run_cli starts mcmd_fillnodata through /bin/sh when given a prefix: exec ours instead.
  return run_cli(args, std::string("exec '") + MCMD_TERRAIN_EXE + "' \"$@\";");
}

void write_image(const std::string& path, const Image& img, const char* driver, int epsg,
                 const std::array<double, 6>* transform, const double* nodata) {
  GDALAllRegister();
  Ds mem(GetGDALDriverManager()->GetDriverByName("MEM")->Create("", img.w, img.h, img.bands, img.type, nullptr));
  for (int b = 0; b < img.bands; ++b) {
    GDALRasterBand* band = mem->GetRasterBand(b + 1);
    if (band->RasterIO(GF_Write, 0, 0, img.w, img.h,
                       const_cast<double*>(img.values.data() + static_cast<std::size_t>(b) * img.w * img.h), img.w,
                       img.h, GDT_Float64, 0, 0, nullptr) != CE_None)
      throw std::runtime_error("cannot write a test image");
    if (nodata) band->SetNoDataValue(*nodata);
  }
  if (transform) mem->SetGeoTransform(const_cast<double*>(transform->data()));
  if (epsg) {
    OGRSpatialReference srs;
    srs.importFromEPSG(epsg);
    mem->SetSpatialRef(&srs);
  }
  Ds out(GetGDALDriverManager()->GetDriverByName(driver)->CreateCopy(path.c_str(), mem.get(), FALSE, nullptr, nullptr,
                                                                     nullptr));
  if (!out) throw std::runtime_error("cannot create " + path);
}

Image read_image(const std::string& path, int band) {
  GDALAllRegister();
  Ds ds(GDALDataset::Open(path.c_str(), GDAL_OF_RASTER | GDAL_OF_READONLY));
  if (!ds) throw std::runtime_error("cannot open " + path);
  Image img;
  img.w = ds->GetRasterXSize();
  img.h = ds->GetRasterYSize();
  img.type = ds->GetRasterBand(band)->GetRasterDataType();
  img.values.resize(static_cast<std::size_t>(img.w) * img.h);
  if (ds->GetRasterBand(band)->RasterIO(GF_Read, 0, 0, img.w, img.h, img.values.data(), img.w, img.h, GDT_Float64, 0,
                                        0, nullptr) != CE_None)
    throw std::runtime_error("cannot read " + path);
  return img;
}

void write_test_sketch(const std::string& sketch, const std::string& states, int n) {
  Image grey{n, n, 1, GDT_UInt16, std::vector<double>(static_cast<std::size_t>(n) * n, 65535.0)};
  Image colour{n, n, 3, GDT_Byte, std::vector<double>(3 * static_cast<std::size_t>(n) * n, 0.0)};
  for (const SketchLine& l : sketch_lines(n))
    for (std::size_t k = 0; k < l.cells.size(); ++k) {
      const std::size_t i = static_cast<std::size_t>(l.cells[k].second) * n + l.cells[k].first;
      grey.values[i] = std::round(l.z[k] * 10.0);
      colour.values[(l.river ? 2 : 0) * static_cast<std::size_t>(n) * n + i] = 255;
    }
  write_image(sketch, grey, "PNG");
  write_image(states, colour, "PNG");
}

}  // namespace mcmd::test
