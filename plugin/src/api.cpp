// The C API: MCMDFillNodata(), GDALFillNodata's contract with MCMD inside.
#include "errors.hpp"
#include "fill_band.hpp"
#include "mcmd_gdal.h"
#include "options.hpp"

namespace {

mcmd::ProgressFn progress_of(GDALProgressFunc fn, void* arg) {
  if (!fn) return {};
  return [fn, arg](double f) { return fn(f, "", arg) != FALSE; };
}

}  // namespace

extern "C" CPLErr MCMDFillNodata(GDALRasterBandH hTargetBand, GDALRasterBandH hMaskBand,
                                 CSLConstList papszOptions, GDALProgressFunc pfnProgress, void* pProgressArg) {
  using namespace mcmd::gdal;
  return guarded([&] {
    if (!hTargetBand) throw Failure(CPLE_ObjectNull, "MCMDFillNodata: hTargetBand is NULL");
    const Options options = parse_options(papszOptions);
    auto& band = *GDALRasterBand::FromHandle(hTargetBand);
    FillRequest request;
    GDALRasterBand* mask = hMaskBand ? GDALRasterBand::FromHandle(hMaskBand) : own_mask(band);
    if (mask) request.masks.push_back(mask);
    request.use_nodata = hMaskBand == nullptr;
    request.band_number = band.GetBand();
    fill_band(band, request, options, progress_of(pfnProgress, pProgressArg));
  });
}
