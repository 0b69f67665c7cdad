#include "lib/blank_source.hpp"

#include <cstring>

#include "gdal_proxy.h"

namespace mcmd::gdal {

namespace {

class BlankBand final : public GDALProxyRasterBand {
 public:
  explicit BlankBand(GDALRasterBand& source) : source_(source) {
    nRasterXSize = source.GetXSize();
    nRasterYSize = source.GetYSize();
    eDataType = source.GetRasterDataType();
    source.GetBlockSize(&nBlockXSize, &nBlockYSize);
    eAccess = GA_ReadOnly;
  }

  // GDAL 3.6's proxy forwards GetNoDataValue only: a copy of a 64-bit
  // integer band lost its nodata value.
  int64_t GetNoDataValueAsInt64(int* ok) override { return source_.GetNoDataValueAsInt64(ok); }
  uint64_t GetNoDataValueAsUInt64(int* ok) override { return source_.GetNoDataValueAsUInt64(ok); }

 protected:
  GDALRasterBand* RefUnderlyingRasterBand() const override { return &source_; }

  CPLErr IRasterIO(GDALRWFlag rw, int x, int y, int w, int h, void* buf, int buf_w, int buf_h, GDALDataType type,
                   GSpacing pixel_space, GSpacing line_space, GDALRasterIOExtraArg* extra) override {
    if (rw != GF_Read)
      return GDALProxyRasterBand::IRasterIO(rw, x, y, w, h, buf, buf_w, buf_h, type, pixel_space, line_space, extra);
    const double zero = 0.0;
    for (int r = 0; r < buf_h; ++r)  // a zero into every pixel, whatever the spacing
      GDALCopyWords64(&zero, GDT_Float64, 0, static_cast<GByte*>(buf) + r * line_space, type,
                      static_cast<int>(pixel_space), buf_w);
    return CE_None;
  }

  CPLErr IReadBlock(int, int, void* block) override {
    std::memset(block, 0,
                static_cast<std::size_t>(nBlockXSize) * nBlockYSize * GDALGetDataTypeSizeBytes(eDataType));
    return CE_None;
  }

 private:
  GDALRasterBand& source_;
};

class BlankDataset final : public GDALProxyDataset {
 public:
  explicit BlankDataset(GDALDataset& source) : source_(source) {
    nRasterXSize = source.GetRasterXSize();
    nRasterYSize = source.GetRasterYSize();
    eAccess = GA_ReadOnly;
    SetDescription(source.GetDescription());
    SetBand(1, new BlankBand(*source.GetRasterBand(1)));
  }

 protected:
  GDALDataset* RefUnderlyingDataset() const override { return &source_; }

  // GDALProxyDataset sends dataset reads to the source: here they go through
  // the band (GDALDataset's own way).
  CPLErr IRasterIO(GDALRWFlag rw, int x, int y, int w, int h, void* buf, int buf_w, int buf_h, GDALDataType type,
                   int band_count, int* bands, GSpacing pixel_space, GSpacing line_space, GSpacing band_space,
                   GDALRasterIOExtraArg* extra) override {
    return GDALDataset::IRasterIO(rw, x, y, w, h, buf, buf_w, buf_h, type, band_count, bands, pixel_space,
                                  line_space, band_space, extra);
  }

 private:
  GDALDataset& source_;
};

}  // namespace

std::unique_ptr<GDALDataset> blank_source(GDALDataset& source) { return std::make_unique<BlankDataset>(source); }

}  // namespace mcmd::gdal
