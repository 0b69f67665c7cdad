#include "lib/band_access.hpp"

#include <algorithm>
#include <string>
#include <utility>

#include "lib/band_window.hpp"
#include "lib/errors.hpp"

namespace mcmd::gdal {

namespace {

std::size_t cell_count(GDALRasterBand& band) {
  return static_cast<std::size_t>(band.GetXSize()) * static_cast<std::size_t>(band.GetYSize());
}

// Calls f(c, end) for each maximal run [c, end) of non-zero bytes of mask[0, n).
template <class F>
void for_each_set_run(const std::uint8_t* mask, std::size_t n, F&& f) {
  for (std::size_t c = 0; c < n;) {
    if (!mask[c]) {
      ++c;
      continue;
    }
    std::size_t end = c;
    while (end < n && mask[end]) ++end;
    f(c, end);
    c = end;
  }
}

}  // namespace

BandAccess::BandAccess(GDALRasterBand& source, GDALRasterBand& target, const FillRequest& request)
    : BandAccess(source, [&target]() -> GDALRasterBand& { return target; }, request) {
  target_ = &target;
  target_type_ = pixel_type_of(target);
  in_place_ = &source == &target;
  if (in_place_) written_.assign((cell_count(source) + 63) / 64, 0);
}

BandAccess::BandAccess(GDALRasterBand& source, TargetBand target, const FillRequest& request)
    : source_(source),
      get_target_(std::move(target)),
      request_(request),
      source_type_(pixel_type_of(source)),
      in_place_(false) {
  for (GDALRasterBand* mask : request.masks) check_mask_size(*mask, source);
  if (request.blank_target) written_.assign((cell_count(source) + 63) / 64, 0);
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
  NativeCells* keep = request_.blank_target && whole(x0, y0, w, h) ? &kept_ : nullptr;
  read_cells(source_, source_type_, request_.masks, Window{x0, y0, w, h}, request_.use_nodata, z, valid, nullptr,
             keep);
  if (!in_place_) return;
  const std::size_t W = static_cast<std::size_t>(source_.GetXSize());
  for (int r = 0; r < h; ++r) {
    std::uint8_t* row = valid + static_cast<std::size_t>(r) * w;
    for_each_written((static_cast<std::size_t>(y0) + r) * W + static_cast<std::size_t>(x0), static_cast<std::size_t>(w),
                     [row](std::size_t c) { row[c] = 0; });
  }
}

void BandAccess::write(int x0, int y0, int w, int h, const double* z, const std::uint8_t* mask) {
  GDALRasterBand& out = target();
  if (request_.blank_target && kept_.type == target_type_.gdt && whole(x0, y0, w, h)) {
    write_over_kept(z, mask);
    return;
  }
  const int bytes = GDALGetDataTypeSizeBytes(target_type_.gdt);
  run_.resize(static_cast<std::size_t>(w) * bytes);
  const std::size_t W = static_cast<std::size_t>(out.GetXSize());
  for (int r = 0; r < h; ++r) {
    const std::size_t base = static_cast<std::size_t>(r) * w;
    for_each_set_run(mask + base, static_cast<std::size_t>(w), [&](std::size_t c, std::size_t end) {
      const int n = static_cast<int>(end - c), x = x0 + static_cast<int>(c);
      encode(target_type_, z + base + c, end - c, run_.data());
      check_io(out.RasterIO(GF_Write, x, y0 + r, n, 1, run_.data(), n, 1, target_type_.gdt, 0, 0, nullptr),
               "cannot write the filled cells");
      if (!written_.empty())
        for (std::size_t k = c; k < end; ++k)
          mark_written((static_cast<std::size_t>(y0) + r) * W + static_cast<std::size_t>(x0) + k);
    });
  }
}

// The whole band in one request: the filled cells encoded over the source's
// cells as read (kept_, which this uses up), known and unfilled cells as they were.
void BandAccess::write_over_kept(const double* z, const std::uint8_t* mask) {
  const int W = source_.GetXSize(), H = source_.GetYSize();
  const std::size_t n = cell_count(source_);
  const int bytes = GDALGetDataTypeSizeBytes(target_type_.gdt);
  auto* cells = static_cast<unsigned char*>(kept_.data.get());
  for_each_set_run(mask, n,
                   [&](std::size_t c, std::size_t end) { encode(target_type_, z + c, end - c, cells + c * bytes); });
  check_io(target().RasterIO(GF_Write, 0, 0, W, H, cells, W, H, target_type_.gdt, 0, 0, nullptr),
           "cannot write the filled cells");
  std::fill(written_.begin(), written_.end(), ~std::uint64_t{0});
  kept_ = NativeCells{};
}

void BandAccess::complete() {
  if (!request_.blank_target) return;
  const int W = source_.GetXSize(), H = source_.GetYSize();
  const int rows = std::clamp((1 << 20) / std::max(W, 1), 1, std::max(H, 1));  // ~a million cells a request
  for (int y = 0; y < H; y += rows) complete_rows(y, std::min(rows, H - y));
  kept_ = NativeCells{};
}

// Rows [y0, y0 + rows): the cells not written, copied from the source (kept_
// or read again) into the target, in the band's own type.
void BandAccess::complete_rows(int y0, int rows) {
  const int W = source_.GetXSize();
  const std::size_t first = static_cast<std::size_t>(y0) * W, n = static_cast<std::size_t>(rows) * W;
  std::size_t missing = 0;
  for (std::size_t i = first; i < first + n; ++i) missing += !was_written(i);
  if (missing == 0) return;
  GDALRasterBand& out = target();
  const GDALDataType gdt = target_type_.gdt;
  const int bytes = GDALGetDataTypeSizeBytes(gdt);
  std::vector<unsigned char> from(n * bytes);
  if (kept_.type == gdt)
    std::copy_n(static_cast<const unsigned char*>(kept_.data.get()) + first * bytes, n * bytes, from.begin());
  else
    check_io(source_.RasterIO(GF_Read, 0, y0, W, rows, from.data(), W, rows, gdt, 0, 0, nullptr),
             "cannot read the band");
  std::vector<unsigned char> to;
  if (missing < n) {  // keep what the fill wrote
    to.resize(n * bytes);
    check_io(out.RasterIO(GF_Read, 0, y0, W, rows, to.data(), W, rows, gdt, 0, 0, nullptr),
             "cannot read the output back");
    for (std::size_t i = 0; i < n; ++i)
      if (!was_written(first + i)) std::copy_n(from.begin() + i * bytes, bytes, to.begin() + i * bytes);
  } else {
    to.swap(from);
  }
  check_io(out.RasterIO(GF_Write, 0, y0, W, rows, to.data(), W, rows, gdt, 0, 0, nullptr),
           "cannot write the known cells");
  for (std::size_t i = first; i < first + n; ++i) mark_written(i);
}

}  // namespace mcmd::gdal
