// The C API: MCMDFillNodata(), GDALFillNodata's contract with MCMD inside.
#include "lib/errors.hpp"
#include "lib/fill_band.hpp"
#include "lib/options.hpp"
#include "mcmd_gdal.h"

namespace {

mcmd::ProgressFn progress_of(GDALProgressFunc fn, void* arg) {
  if (!fn) return {};
  return [fn, arg](double f) { return fn(f, "", arg) != FALSE; };
}

}  // namespace

#ifndef MCMD_VERSION
#define MCMD_VERSION "unknown"
#endif

extern "C" const char* MCMDVersion(void) { return MCMD_VERSION; }

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
