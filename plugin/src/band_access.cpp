#include "band_access.hpp"

#include <algorithm>
#include <string>
#include <utility>

#include "band_window.hpp"
#include "errors.hpp"

namespace mcmd::gdal {

BandAccess::BandAccess(GDALRasterBand& source, GDALRasterBand& target, const FillRequest& request)
    : BandAccess(source, [&target]() -> GDALRasterBand& { return target; }, request) {
  target_ = &target;
  target_type_ = pixel_type_of(target);
  in_place_ = &source == &target;
  if (in_place_) {
    const std::size_t cells = static_cast<std::size_t>(source.GetXSize()) * static_cast<std::size_t>(source.GetYSize());
    written_.assign((cells + 63) / 64, 0);
  }
}

BandAccess::BandAccess(GDALRasterBand& source, TargetBand target, const FillRequest& request)
    : source_(source),
      get_target_(std::move(target)),
      request_(request),
      source_type_(pixel_type_of(source)),
      in_place_(false) {
  for (GDALRasterBand* mask : request.masks) check_mask_size(*mask, source);
}

GDALRasterBand& BandAccess::target() {
  if (!target_) {
    target_ = &get_target_();
    target_type_ = pixel_type_of(*target_);
  }
  return *target_;
}

bool BandAccess::nodata_marks_voids() const {
  return request_.use_nodata && source_type_.signed_byte && source_type_.has_nodata;
}

RasterAccess BandAccess::access() {
  RasterAccess a;
  a.width = source_.GetXSize();
  a.height = source_.GetYSize();
  a.read = [this](int x0, int y0, int w, int h, double* z, std::uint8_t* valid) { read(x0, y0, w, h, z, valid); };
  a.write = [this](int x0, int y0, int w, int h, const double* z, const std::uint8_t* mask) {
    write(x0, y0, w, h, z, mask);
  };
  return a;
}

void BandAccess::read(int x0, int y0, int w, int h, double* z, std::uint8_t* valid) {
  read_cells(source_, source_type_, request_.masks, Window{x0, y0, w, h}, request_.use_nodata, z, valid, nullptr);
  if (!in_place_) return;
  const std::size_t W = static_cast<std::size_t>(source_.GetXSize());
  for (int r = 0; r < h; ++r)
    for (int c = 0; c < w; ++c)
      if (was_written((static_cast<std::size_t>(y0) + r) * W + static_cast<std::size_t>(x0) + c))
        valid[static_cast<std::size_t>(r) * w + c] = 0;
}

void BandAccess::write(int x0, int y0, int w, int h, const double* z, const std::uint8_t* mask) {
  GDALRasterBand& out = target();
  const int bytes = GDALGetDataTypeSizeBytes(target_type_.gdt);
  run_.resize(static_cast<std::size_t>(w) * bytes);
  const std::size_t W = static_cast<std::size_t>(out.GetXSize());
  for (int r = 0; r < h; ++r) {
    const std::size_t base = static_cast<std::size_t>(r) * w;
    for (int c = 0; c < w;) {
      if (!mask[base + c]) {
        ++c;
        continue;
      }
      int end = c;
      while (end < w && mask[base + end]) ++end;
      encode(target_type_, z + base + c, static_cast<std::size_t>(end - c), run_.data());
      if (out.RasterIO(GF_Write, x0 + c, y0 + r, end - c, 1, run_.data(), end - c, 1, target_type_.gdt, 0, 0,
                           nullptr) != CE_None) {
        const std::string detail = CPLGetLastErrorMsg();
        throw Failure(CPLE_FileIO, "cannot write the filled cells" + (detail.empty() ? "" : ": " + detail));
      }
      if (in_place_)
        for (int k = c; k < end; ++k) {
          const std::size_t cell = (static_cast<std::size_t>(y0) + r) * W + static_cast<std::size_t>(x0) + k;
          written_[cell >> 6] |= std::uint64_t{1} << (cell & 63);
        }
      c = end;
    }
  }
}

}  // namespace mcmd::gdal
