#include "fill_band.hpp"

#include <string>

#include "band_window.hpp"
#include "errors.hpp"
#include "mcmd/distance.hpp"
#include "mcmd/fill.hpp"
#include "mcmd/padding.hpp"

namespace mcmd::gdal {

namespace {

std::string band_name(const FillRequest& r) {
  return r.band_number > 0 ? "band " + std::to_string(r.band_number) : "the band";
}

void check_fillable(const WindowData& d, const FillRequest& r) {
  if (r.require_void_marker && !d.voids_marked)
    throw Failure(CPLE_AppDefined, band_name(r) +
                                       " has no nodata value, mask or NaN cell: nothing marks the voids "
                                       "(set a nodata value, e.g. gdal_edit.py -a_nodata, or pass -mask)");
  if (d.void_count == d.z.size())
    throw Failure(CPLE_AppDefined, band_name(r) + " has no valid cell: nothing to fill from");
}

// Cells to write: void cells within max_distance of a valid cell (0 = all voids).
std::vector<std::uint8_t> cells_to_write(const WindowData& d, double max_distance) {
  std::vector<std::uint8_t> write(d.valid.size());
  for (std::size_t i = 0; i < write.size(); ++i) write[i] = d.valid[i] ? 0 : 1;
  if (max_distance <= 0) return write;
  const std::vector<double> dist = distance_to_valid(d.valid.data(), d.win.w, d.win.h);
  for (std::size_t i = 0; i < write.size(); ++i)
    if (dist[i] > max_distance) write[i] = 0;
  return write;
}

// Fill the window's voids; returns the window's elevations with voids filled.
std::vector<double> fill_window(const WindowData& d, const Options& options, const ProgressFn& progress) {
  const int n = levels_to_cover(d.win.w, d.win.h);
  Grid grid = mirror_padded_grid(d.z.data(), d.valid.data(), d.win.w, d.win.h, n);
  fill(grid, options.fill, progress);
  std::vector<double> out(d.z.size());
  for (int y = 0; y < d.win.h; ++y)
    for (int x = 0; x < d.win.w; ++x) out[static_cast<std::size_t>(y) * d.win.w + x] = grid.z(x, y);
  return out;
}

}  // namespace

GDALRasterBand* own_mask(GDALRasterBand& band) {
  return band.GetMaskFlags() == GMF_ALL_VALID ? nullptr : band.GetMaskBand();
}

void check_band(GDALRasterBand& band, const FillRequest& request) {
  const PixelType type = pixel_type_of(band);
  const Window win{0, 0, band.GetXSize(), band.GetYSize()};
  check_fillable(read_window(band, type, request.masks, win, request.use_nodata), request);
}

void fill_band(GDALRasterBand& band, const FillRequest& request, const Options& options,
               const ProgressFn& progress) {
  const PixelType type = pixel_type_of(band);
  const Window win{0, 0, band.GetXSize(), band.GetYSize()};
  const WindowData data = read_window(band, type, request.masks, win, request.use_nodata);
  check_fillable(data, request);
  report(progress, 0.0);
  if (data.void_count == 0) {
    report(progress, 1.0);
    return;
  }
  const std::vector<std::uint8_t> write = cells_to_write(data, options.max_distance);
  const std::vector<double> filled = fill_window(data, options, sub_progress(progress, 0.05, 0.95));
  write_cells(band, type, win, filled, write);
  report(progress, 1.0);
}

}  // namespace mcmd::gdal
