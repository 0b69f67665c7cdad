#include "cli/help.hpp"

#include "gdal.h"

#ifndef MCMD_VERSION
#define MCMD_VERSION "unknown"
#endif

namespace mcmd::cli {

std::string version_text() {
  return std::string("mcmd_fillnodata ") + MCMD_VERSION + " (GDAL " + GDALVersionInfo("RELEASE_NAME") + ")\n";
}

std::string help_text() {
  return R"(Usage: mcmd_fillnodata [options] src_file [dst_file]

Fill the nodata voids of a raster (a DEM first of all) with MCMD, Morphologically
Constrained Midpoint Displacement. Valid cells are copied bit for bit; only void
cells are written. Without dst_file, src_file is edited in place (as
gdal_fillnodata does: a crash while writing may leave it partly filled).

What is a void: the band's nodata value, its mask or alpha band, NaN (or
infinite) cells of float bands, and with -mask the cells where the mask file is 0.

Input and output:
  -b band          Fill only this band (1-based, repeatable). Default: every band
                   except alpha bands. Other bands are copied unchanged.
  -mask file       Validity mask raster of the same size: 0 = void, anything else
                   = valid. Its voids are added to the band's own nodata/mask.
  -nomask          Ignore the band's own nodata value, mask and alpha band; only
                   -mask and NaN cells then mark voids.
  -of format       GDAL output driver (GTiff, COG, ...). Default: guessed from the
                   dst_file extension, else GTiff. Type, size, CRS, geotransform,
                   nodata value, metadata, colour interpretation and band
                   descriptions are kept.
  -co NAME=VALUE   Creation option of the output driver (repeatable), e.g.
                   -co COMPRESS=DEFLATE.
  -q               Quiet: print no progress.
  --help           This text.    --version   Version of mcmd and GDAL.
  GDAL's general options are accepted too (--config KEY VALUE, --debug on,
  --formats, --optfile file, ...; see --help-general).

Shape of the fill (what it does to the terrain):
  -method m        mcmd (default): smooth, thin-plate-like surface that follows
                   the slopes around each void (most accurate). paper-ds /
                   paper-te: the published MCMD method exactly, on a
                   diamond-square or triangle-edge subdivision (for comparison).
  -md distance     Maximum fill distance in cells: void cells farther than this
                   from any valid cell are left as nodata. 0 (default) = fill
                   every void, however large.
  -inner           Fill only inner holes: voids that touch the raster's border
                   (the sea, the outside of a survey footprint, scene edges)
                   stay nodata. A void is a set of void cells connected through
                   their 8 neighbours, judged whole however many tiles it
                   crosses: mcmd_fillnodata -inner nz.tif nz_filled.tif.
  -fill-from file  Delta surface fill: take the voids' shape from a second DEM
                   of the area (any CRS, resolution and extent: warped onto
                   this raster's grid, cubic; -o FILL_FROM_RESAMPLING=bilinear)
                   and interpolate only the difference between the two DEMs,
                   faded with the distance from the rim: no step at the rim.
                   Voids it does not cover get the plain fill:
                   mcmd_fillnodata -fill-from gtopo30.tif srtm.tif filled.tif.
  -maxvoid size    Leave voids larger than this unfilled: a number of cells
                   (-maxvoid 5000, -maxvoid 5000cells) or an area in m2, km2
                   or ha (-maxvoid 2.5km2; geographic rasters: cell areas at
                   their central latitude). Combines with -md and -inner.
  -I value         Paper methods only (-method paper-ds, paper-te; no effect
                   on the default): shape of the top-down interpolation (the
                   paper's I, default 0). 0 blends the surrounding terrain
                   evenly; I > 0 favours nearby cells and gives rounded,
                   bell-like fills; I < 0 favours distant cells and gives
                   sharper, ridge-like fills. Range [-100, 100].
  -Ibu value       Paper methods only: the same shape for the bottom-up pass
                   that first propagates the known elevations into the void
                   (the paper's I_bu, default 0).
  -delta form      Paper methods only. normalized (default): weighted mean, a
                   fill that does not depend on the elevation datum (filling
                   z+c gives fill+c). paper: the paper's formula, which pulls
                   fills towards 0 m when I != 0.
  -rs value|auto   Roughness: amplitude of the random relief added to the fill,
                   as a FRACTION OF THE KNOWN ELEVATION RANGE of the band (0.01 on
                   a DEM spanning 1000 m = about 10 m of relief). 0 (default) = a
                   smooth fill. With m, an amplitude in elevation units (metres on
                   a DEM in metres): -rs 20m. auto = amplitude and H measured from
                   the known terrain around the voids, so the fill looks as rough
                   as its surroundings.
  -H value         Hurst exponent in [0, 1] (default 0.5): how the relief fades
                   from coarse to fine scales. High H = smooth, rolling relief;
                   low H = rugged, noisy relief. Only matters with -rs > 0.
  -rt value        Paper methods only: bias of the random relief in [-1, 1]
                   (default 0): > 0 raises, < 0 lowers the filled terrain on
                   average. Only with -rs > 0.
  -seed n          Seed of the random relief (default 0). The same seed gives
                   bit-identical output; the relief at a cell depends only on
                   (seed, cell position), not on tiling or threads.
  -o NAME=VALUE    Any other MCMDFillNodata option, e.g. -o MORPH_CHANNEL=500.

Morphology (valleys and ridges through the voids; docs/morphology.md):
  -morph auto      Route the known terrain's drainage through each void: a
                   valley that enters a void leaves it downstream, at its
                   outlet, falling all the way (no dam, no pond upstream), and
                   no filled cell is left in a closed depression. For
                   hydrology (streams, watersheds, flood models). Default
                   none. -o MORPH_CHANNEL=N: cells that must drain into a void
                   to make a channel through it (default 0.1 % of the known
                   cells, at most 2000). Above 2^21 cells (filled through
                   tiles) only voids up to 128 cells across get channels.
  -rivers file     River lines: vector lines in any OGR format (reprojected to
                   the raster's CRS) or a raster mask on the raster's grid
                   (nonzero = river). Where a line crosses a void its cells
                   fall from where it enters to where it leaves, the higher
                   end to the lower (following the fill's valley floor with
                   the default method, steadily with a paper method; or the
                   lines' Z), and water runs along them.
  -ridges file     Ridge lines, likewise: the crest of the fill where they
                   cross a void.
                   With the paper methods, river and ridge cells take their own
                   -o RIVER_I / RIVER_I_BU / RIDGE_I / RIDGE_I_BU (the paper's
                   shape parameters); with the default method RIVER_I and
                   RIDGE_I (-100..100) shape the cross-profile within 8 cells
                   of the line: > 0 a flat-floored valley, a rounded crest;
                   < 0 a V valley, a sharp crest; 0 (default) the fill's own.

Performance (with -method mcmd a band of up to 2^21 cells is filled whole, one
field per void; a larger one, or a paper method, is streamed through square
tiles, and memory depends on the tile size and thread count, not on the raster
size; docs/tiling.md):
  -tile size       Tile side in cells when tiling, 2^n+1 (e.g. 129, 257, 513);
                   0 = automatic (513 with -method mcmd, 129 with a paper
                   method, or less for a raster that fits in a smaller
                   tile). -o TILING=ALWAYS tiles small rasters too. Memory
                   per thread: about 40 MB at 513 with -method mcmd; a
                   paper method solves a window twice the tile (about 25 MB
                   at 257, 90 MB at 513). The result is bit-identical for a
                   given tile size, whatever the thread count.
  -threads n       Worker threads solving tiles or voids, a number or ALL_CPUS
                   (default).
  GDAL_CACHEMAX    GDAL's block cache; 64 MB unless set (--config or environment).

Example:
  mcmd_fillnodata -of GTiff -co COMPRESS=DEFLATE dem_with_holes.tif dem_filled.tif

Method: F. Belhadj, "Terrain modeling: a constrained fractal model", AFRIGRAPH
2007, pp. 197-204 (MCMD). The default method keeps its bottom-up/top-down
structure with thin-plate relaxation (docs/default-method.md).
)";
}

}  // namespace mcmd::cli
