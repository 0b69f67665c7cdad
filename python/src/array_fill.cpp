#include "array_fill.hpp"

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <string>

#include "cli/dataset.hpp"
#include "cli/error_log.hpp"
#include "cpl_string.h"
#include "lib/errors.hpp"
#include "lib/fill_band.hpp"
#include "memdataset.h"

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

// A MEM band over `cells` that marks in `filled` every cell written to it
// (the fill writes void cells only, through RasterIO).
class RecordingBand final : public MEMRasterBand {
 public:
  RecordingBand(GDALDataset* ds, GByte* cells, GDALDataType type, bool signed_byte, std::uint8_t* filled)
      : MEMRasterBand(ds, 1, cells, type, 0, 0, FALSE, signed_byte ? "SIGNEDBYTE" : nullptr), filled_(filled) {}

 protected:
  CPLErr IRasterIO(GDALRWFlag flag, int x0, int y0, int w, int h, void* data, int buf_w, int buf_h,
                   GDALDataType buf_type, GSpacing pixel_space, GSpacing line_space,
                   GDALRasterIOExtraArg* extra) override {
    if (flag == GF_Write)
      for (int y = y0; y < y0 + h; ++y)
        std::fill_n(filled_ + static_cast<std::size_t>(y) * nRasterXSize + x0, w, std::uint8_t{1});
    return MEMRasterBand::IRasterIO(flag, x0, y0, w, h, data, buf_w, buf_h, buf_type, pixel_space, line_space,
                                    extra);
  }

 private:
  std::uint8_t* filled_;
};

// A one-band MEM dataset whose band records the cells written (RecordingBand).
DatasetPtr wrap_recording(void* cells, GDALDataType type, bool signed_byte, int width, int height,
                          std::uint8_t* filled) {
  DatasetPtr ds(MEMDataset::Create("", width, height, 0, type, nullptr));
  if (!ds) throw gdal::Failure(CPLE_AppDefined, std::string("cannot wrap the array as a raster: ") + CPLGetLastErrorMsg());
  auto* band = new RecordingBand(ds.get(), static_cast<GByte*>(cells), type, signed_byte, filled);
  static_cast<MEMDataset*>(ds.get())->AddMEMBand(GDALRasterBand::ToHandle(band));
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

MemoryBand::MemoryBand(const MemoryRaster& raster, const std::uint8_t* valid, const Nodata& nodata,
                       std::uint8_t* filled) {
  ds_ = filled ? wrap_recording(raster.cells, raster.type, raster.signed_byte, raster.width, raster.height, filled)
               : wrap(raster.cells, raster.type, raster.width, raster.height);
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
                        const gdal::Options& options, const ProgressFn& progress, std::uint8_t* filled) {
  cli::ErrorLog log;  // GDAL's own messages stay quiet: failures are thrown
  MemoryBand band(raster, valid, nodata, filled);
  gdal::fill_band(band.band(), band.request(), options, progress);
}

}  // namespace mcmd::python
