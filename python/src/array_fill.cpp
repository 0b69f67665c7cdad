#include "array_fill.hpp"

#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <string>

#include "cli/dataset.hpp"
#include "cli/error_log.hpp"
#include "cpl_string.h"
#include "lib/errors.hpp"
#include "lib/fill_band.hpp"

namespace mcmd::python {

using cli::DatasetPtr;

namespace {

// A one-band MEM dataset over `cells` (not copied, not owned).
DatasetPtr wrap(void* cells, GDALDataType type, int width, int height) {
  GDALDriver* mem = GetGDALDriverManager()->GetDriverByName("MEM");
  if (!mem) throw gdal::Failure(CPLE_AppDefined, "GDAL's MEM driver is not available");
  DatasetPtr ds(mem->Create("", width, height, 0, type, nullptr));
  char pointer[64];
  std::snprintf(pointer, sizeof pointer, "%p", cells);
  CPLStringList band_options;
  band_options.SetNameValue("DATAPOINTER", pointer);  // row-major, packed: MEM's default offsets
  if (!ds || ds->AddBand(type, band_options.List()) != CE_None)
    throw gdal::Failure(CPLE_AppDefined, std::string("cannot wrap the array as a raster: ") + CPLGetLastErrorMsg());
  return ds;
}

void set_nodata(GDALRasterBand& band, const Nodata& nodata) {
  CPLErr err = CE_None;
  if (const auto* d = std::get_if<double>(&nodata)) err = band.SetNoDataValue(*d);
  if (const auto* i = std::get_if<std::int64_t>(&nodata)) err = band.SetNoDataValueAsInt64(*i);
  if (const auto* u = std::get_if<std::uint64_t>(&nodata)) err = band.SetNoDataValueAsUInt64(*u);
  gdal::check_io(err, "cannot set the nodata value");
}

}  // namespace

MemoryRaster memory_raster(const char* gdal_type_name, void* cells, int width, int height) {
  MemoryRaster r{cells, GDALGetDataTypeByName(gdal_type_name), false, width, height};
#if GDAL_VERSION_NUM < GDAL_COMPUTE_VERSION(3, 7, 0)
  if (std::strcmp(gdal_type_name, "Int8") == 0) {
    r.type = GDT_Byte;
    r.signed_byte = true;
  }
#endif
  if (r.type == GDT_Unknown || GDALDataTypeIsComplex(r.type))
    throw std::invalid_argument(std::string("unsupported GDAL data type '") + gdal_type_name + "'");
  return r;
}

MemoryBand::MemoryBand(const MemoryRaster& raster, const std::uint8_t* valid, const Nodata& nodata) {
  ds_ = wrap(raster.cells, raster.type, raster.width, raster.height);
  band_ = ds_->GetRasterBand(1);
  if (raster.signed_byte) band_->SetMetadataItem("PIXELTYPE", "SIGNEDBYTE", "IMAGE_STRUCTURE");
  set_nodata(*band_, nodata);
  // As the CLI asks for a band (cli/run.cpp).
  if (valid) {
    mask_ds_ = wrap(const_cast<std::uint8_t*>(valid), GDT_Byte, raster.width, raster.height);
    request_.masks.push_back(mask_ds_->GetRasterBand(1));
  }
  if (GDALRasterBand* own = gdal::own_mask(*band_)) request_.masks.push_back(own);
  request_.require_void_marker = true;
}

MemoryBand::~MemoryBand() {
  if (ds_) ds_->FlushCache();
}

void fill_memory_raster(const MemoryRaster& raster, const std::uint8_t* valid, const Nodata& nodata,
                        const gdal::Options& options, const ProgressFn& progress) {
  cli::ErrorLog log;  // GDAL's own messages stay quiet: failures are thrown
  MemoryBand band(raster, valid, nodata);
  gdal::fill_band(band.band(), band.request(), options, progress);
}

}  // namespace mcmd::python
