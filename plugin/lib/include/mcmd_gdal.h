/* mcmd GDAL API: fill nodata voids of a raster band with MCMD.
 *
 * MCMDFillNodata() mirrors GDALFillNodata(): every cell of hTargetBand marked
 * invalid is interpolated in place; valid cells are never written.
 *
 *  hTargetBand  band to fill, opened for update.
 *  hMaskBand    validity mask (0 = void, anything else = valid), same size as
 *               the band; NULL uses the band's own mask (nodata value, alpha
 *               band or per-dataset mask). NaN cells of float bands are always
 *               voids.
 *  papszOptions NAME=VALUE options, all optional (parsed in plugin/lib/options.cpp):
 *               METHOD=mcmd|paper-ds|paper-te, DELTA=normalized|paper,
 *               I, I_BU, RIDGE_I, RIDGE_I_BU, RIVER_I, RIVER_I_BU, H, RT,
 *               RS=<fraction of the known elevation range>|<amplitude>m|auto, SEED,
 *               MAX_DISTANCE (cells, 0 = unlimited), TILE_SIZE (2^n+1, 0 = auto;
 *               the size used when tiling), TILING (AUTO: rasters up to 2^21
 *               cells are filled whole; ALWAYS: tiles whatever the size),
 *               NUM_THREADS (n|ALL_CPUS). Unknown names are errors.
 *  pfnProgress  GDAL progress callback (may be NULL); returning FALSE stops
 *               the fill with CPLE_UserInterrupt before anything is written.
 *
 * Returns CE_None on success, CE_Failure (with a CPLError message) otherwise.
 */
#ifndef MCMD_GDAL_H_INCLUDED
#define MCMD_GDAL_H_INCLUDED

#include "gdal.h"

/* The library is built with hidden symbols; these are its interface. */
#if defined(_WIN32)
#define MCMD_API __declspec(dllexport)
#elif defined(__GNUC__)
#define MCMD_API __attribute__((visibility("default")))
#else
#define MCMD_API
#endif

#ifdef __cplusplus
extern "C" {
#endif

/* The mcmd version, e.g. "0.1.0". */
MCMD_API const char *MCMDVersion(void);

MCMD_API CPLErr MCMDFillNodata(GDALRasterBandH hTargetBand, GDALRasterBandH hMaskBand,
                      CSLConstList papszOptions, GDALProgressFunc pfnProgress,
                      void *pProgressArg);

/* MCMDTerrain(): make a terrain into hTargetBand, opened for update: every
 * cell is written (docs/terrain.md).
 *
 *  hTargetBand  band to write; its size is the terrain's.
 *  hSketchBand  optional constraints (NULL: from scratch or a generator): a
 *               band of the same size whose known cells are kept bit for bit
 *               (with UPSAMPLE=K, the coarse ((W-1)/K+1)x((H-1)/K+1) raster).
 *               Unknown cells: nodata, mask, alpha, NaN, and by UNKNOWN.
 *  papszOptions NAME=VALUE, all optional: METHOD=mcmd|paper|paper-ds|paper-te|
 *               mdi|none, SCHEME=ds|te|butterfly, SHARPNESS, RS=<fraction of
 *               the constraints' range>|<amplitude>m (e.g. 300m), H, RT, SEED,
 *               I, I_BU, RIDGE_I, RIDGE_I_BU, RIVER_I, RIVER_I_BU, DELTA,
 *               UNKNOWN=white|black|none|<value>, ZRANGE=MIN,MAX,
 *               SKELETON=YES, RIDGE_COUPLES, RIVER_PARTICLES,
 *               PEAKS=iizuka|<count>, PEAKS_NOISE, PEAKS_THRESHOLD,
 *               POINTS=col,row,z[;...], STATES=<raster>, RIDGES=<lines>,
 *               RIVERS=<lines> (any OGR format, or a raster mask),
 *               RIDGE_Z=Z[,Z2], RIVER_Z=Z1[,Z2], UPSAMPLE=K,
 *               EROSION=auto|<steps>|NO (default auto for SKELETON and a
 *               terrain without sketch, PEAKS or POINTS; NO otherwise),
 *               EROSION_LAW=K,m,n (K a number or auto), UPLIFT=terrain|
 *               uniform|<raster>, DIFFUSION=<factor>, TALUS=<degrees>,
 *               MEDIAN=N, MEDIAN_PASSES, MEDIAN_ALL=YES, NUM_THREADS.
 *               Unknown names are errors.
 *  pfnProgress  GDAL progress callback (may be NULL); FALSE stops it with
 *               CPLE_UserInterrupt before anything is written.
 *
 * Returns CE_None on success, CE_Failure (with a CPLError message) otherwise.
 */
MCMD_API CPLErr MCMDTerrain(GDALRasterBandH hTargetBand, GDALRasterBandH hSketchBand,
                   CSLConstList papszOptions, GDALProgressFunc pfnProgress,
                   void *pProgressArg);

#ifdef __cplusplus
}
#endif

#endif /* MCMD_GDAL_H_INCLUDED */
