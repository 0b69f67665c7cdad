#include "lib/fill_band.hpp"

#include <algorithm>
#include <memory>
#include <stdexcept>
#include <string>

#include "lib/band_access.hpp"
#include "lib/band_window.hpp"
#include "lib/errors.hpp"
#include "lib/fill_from.hpp"
#include "lib/line_input.hpp"
#include "lib/void_cap.hpp"
#include "mcmd/fill_raster.hpp"

namespace mcmd::gdal {

namespace {

std::string band_name(const FillRequest& r) {
  return r.band_number > 0 ? "band " + std::to_string(r.band_number) : "the band";
}

void fail_unmarked(const FillRequest& r) {
  throw Failure(CPLE_AppDefined, band_name(r) +
                                     " has no nodata value, mask or NaN cell: nothing marks the voids "
                                     "(set a nodata value, e.g. gdal_edit.py -a_nodata, or pass -mask)");
}

void fail_no_valid(const FillRequest& r) {
  throw Failure(CPLE_AppDefined, band_name(r) + " has no valid cell: nothing to fill from");
}

// The ridge and river lines of the options, on the source's grid; a warning
// when a file's lines all miss the raster.
std::vector<Line> lines_of(const Options& options, GDALDataset* source) {
  std::vector<Line> lines;
  const std::pair<const std::string*, CellState> files[] = {{&options.rivers, CellState::river},
                                                           {&options.ridges, CellState::ridge}};
  for (const auto& [path, kind] : files) {
    if (path->empty()) continue;
    if (!source) throw Failure(CPLE_AppDefined, "lines need a band that belongs to a dataset (for its georeferencing)");
    std::vector<Line> read = read_lines(*path, kind, *source);
    if (lines_inside(read, source->GetRasterXSize(), source->GetRasterYSize()) == 0)
      warn("the " + std::string(kind == CellState::ridge ? "ridge" : "river") + " lines of '" + *path +
           "' do not cross the raster: filled without them");
    lines.insert(lines.end(), read.begin(), read.end());
  }
  return lines;
}

// A fill in place that stopped after the tiles had written some of its
// cells (the tiled path writes as it goes): said, with how much.
[[noreturn]] void fail_partly_filled(const FillRequest& r, const RasterFillStats& stats, const std::string& why) {
  throw Failure(why == "cancelled by the user" ? CPLE_UserInterrupt : CPLE_AppDefined,
                why + "; " + band_name(r) + " is partly filled in place (" + std::to_string(stats.cells_written) +
                    " of " + std::to_string(stats.void_cells) + " void cells written; known cells unchanged)");
}

}  // namespace

FillParams fill_params(const Options& options, GDALDataType type) {
  FillParams p = options.fill;
  if (GDALDataTypeIsInteger(type) && !GDALDataTypeIsComplex(type)) p.z_step = 1.0;
  return p;
}

GDALRasterBand* own_mask(GDALRasterBand& band) {
  return band.GetMaskFlags() == GMF_ALL_VALID ? nullptr : band.GetMaskBand();
}

void check_band(GDALRasterBand& band, const FillRequest& request) {
  // Stream full-width row blocks of about a million cells: memory stays bounded.
  const PixelType type = pixel_type_of(band);
  const int W = band.GetXSize(), H = band.GetYSize();
  const int rows = std::clamp((1 << 20) / std::max(W, 1), 1, std::max(H, 1));
  std::size_t voids = 0;
  bool marked = !request.masks.empty();
  for (int y = 0; y < H; y += rows) {
    const WindowData d = read_window(band, type, request.masks, Window{0, y, W, std::min(rows, H - y)},
                                     request.use_nodata);
    voids += d.void_count;
    marked = marked || d.voids_marked;
  }
  if (request.require_void_marker && !marked) fail_unmarked(request);
  if (voids == static_cast<std::size_t>(W) * static_cast<std::size_t>(H)) fail_no_valid(request);
}

namespace {

void fill_band_access(BandAccess& band, const FillRequest& request, const Options& options,
                      const ProgressFn& progress) {
  TilingParams tiling = tiling_of(options);
  tiling.max_void_cells = void_cap_cells(options, band.source_dataset());
  RasterAccess access = band.access();
  access.lines = lines_of(options, band.source_dataset());
  RasterFillStats stats;
  RasterFillHooks hooks;
  hooks.stats = &stats;
  const bool marked = !request.masks.empty() || band.nodata_marks_voids();
  // The core's passes take [0, 0.99]: 100% ("done") is reported only once the
  // band is known to have been fillable, and a cancel at the core's last
  // report (before it writes a one-tile raster) leaves the band untouched.
  const ProgressFn capped = sub_progress(progress, 0.0, 0.99);
  std::unique_ptr<SecondDem> second;
  if (!options.fill_from.empty()) {
    if (options.fill.morph.channels) throw OptionError("FILL_FROM and MORPH=auto do not combine: pick one");
    second = std::make_unique<SecondDem>(options.fill_from, band.source_dataset(), access.width, access.height,
                                         options.fill_from_resampling);
  }
  try {
    if (second)
      fill_raster_from(access, background_of(*second), fill_params(options, band.source_type()), tiling, capped, hooks);
    else
      fill_raster(access, fill_params(options, band.source_type()), tiling, capped, hooks);
  } catch (const std::invalid_argument&) {
    // Checked after the first pass, before anything is written.
    if (stats.void_cells > 0 && stats.known_cells == 0) fail_no_valid(request);
    throw;
  } catch (const Cancelled&) {
    if (band.in_place() && stats.cells_written > 0) fail_partly_filled(request, stats, "cancelled by the user");
    throw;
  } catch (const std::exception& e) {
    if (band.in_place() && stats.cells_written > 0) fail_partly_filled(request, stats, e.what());
    throw;
  }
  if (stats.channels_skipped)
    warn(
        "-morph auto routed no channel through the voids filled through tiles: voids too large to solve alone or "
        "reaching far from data, and every void of a tiled raster with a paper method or -md");
  // Nothing was written when no cell is void.
  if (request.require_void_marker && !marked && stats.void_cells == 0) fail_unmarked(request);
  band.complete();
  report(progress, 1.0);
}

}  // namespace

void fill_band(GDALRasterBand& target, GDALRasterBand& source, const FillRequest& request, const Options& options,
               const ProgressFn& progress) {
  BandAccess band(source, target, request);
  fill_band_access(band, request, options, progress);
}

void fill_band(const TargetBand& target, GDALRasterBand& source, const FillRequest& request, const Options& options,
               const ProgressFn& progress) {
  BandAccess band(source, target, request);
  fill_band_access(band, request, options, progress);
}

void fill_band(GDALRasterBand& band, const FillRequest& request, const Options& options, const ProgressFn& progress) {
  fill_band(band, band, request, options, progress);
}

}  // namespace mcmd::gdal
