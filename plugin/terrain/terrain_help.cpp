#include "terrain/terrain_help.hpp"

#include "cli/help.hpp"

namespace mcmd::cli {

// mcmd_fillnodata's line ("mcmd_fillnodata X.Y.Z (GDAL ...)") with this tool's name.
std::string terrain_version_text() {
  const std::string fill = version_text();
  return "mcmd_terrain" + fill.substr(fill.find(' '));
}

std::string terrain_help_text() {
  return R"(Usage: mcmd_terrain [options] [sketch_file] dst_file

Make a terrain (a DEM) with MCMD, Morphologically Constrained Midpoint
Displacement: from scratch, around the constraints of a sketch drawn in an
image editor (white = unknown, as in the paper), around a generated skeleton
of ridges and rivers, or from Iizuka's closed-form peaks. Constraint cells are
kept bit for bit; every other cell is synthesised. docs/terrain.md has more.

Size and georeferencing:
  -size W H        Size of a terrain made without a sketch, any size, e.g.
                   -size 1025 1025 (2^n+1, the paper's grids) or -size 800 600.
                   With a sketch it must agree with it (or is left out).
  -like file       Copy the size, CRS and geotransform of a template raster:
                   -like dem.tif.
  -a_ullr ulx uly lrx lry   Georeference the output (as gdal_translate):
                   -a_ullr 500000 4200000 530000 4170000.
  -a_srs srs       CRS of the output (EPSG:32611, a WKT or PROJ string, a
                   file): -a_srs EPSG:32611. A GeoTIFF sketch's own is kept.
  -ot type         Output data type (default Float32): -ot Int16.
  -of format       GDAL output driver (default: from the extension, else
                   GTiff): -of COG.
  -co NAME=VALUE   Creation option (repeatable): -co COMPRESS=DEFLATE.
  -a_nodata value  Nodata value of the output (only -method none leaves
                   cells without a value; default NaN, or the type's minimum).
  -hillshade file  Also write a shaded preview (PNG, light from the NW):
                   -hillshade terrain.png.
  -q               Quiet: print no progress (mcmd_terrain -q ...).
  --help           This text.    --version   Version of mcmd and GDAL.

The sketch (a raster GDAL reads: grey PNG, GeoTIFF, a DEM with voids):
  -b band          Band of the sketch holding the grey levels (default 1): -b 2.
  -unknown white|black|none|value   Cells to synthesise, besides nodata,
                   mask, alpha = 0 and NaN cells. Default: white (255 in a
                   Byte sketch, 65535 in a UInt16 one) when the sketch has no
                   nodata value or mask; none otherwise. -unknown 0.
  -zrange MIN MAX  Map grey levels to elevations: 0..255 (Byte) or 0..65535
                   (UInt16) to MIN..MAX (other types: the known cells' own
                   range). Also the elevation range of -skeleton (default
                   0 1000) and of -peaks. -zrange 0 2500.
  -states file     Which sketch cells are ridge and river cells: a raster of
                   the sketch's size where 1 = ridge, 2 = river, or a colour
                   image where red pixels are ridges and blue ones rivers
                   (paint them on a layer of the sketch). Ridges become
                   crests, rivers valleys. -states lines.png.
  -ridges file, -rivers file   Ridge and river lines: vector lines in any
                   format OGR reads (reprojected to the output's CRS; lines
                   without a CRS are refused when the output has one), or a
                   raster mask of the output's size (nonzero = on the line).
                   Their cells become ridge and river cells:
                   -ridges crests.gpkg.
  -ridge-z Z[,Z2], -river-z Z1[,Z2]   Heights of line cells that have none
                   (no Z in the lines, no sketch cell under them, no known
                   cells at both ends of their run): one value, or the first
                   and last point's along the line (a river from its source
                   down): -river-z 480,80.
  -point col row z Add a constraint cell (repeatable), e.g. corners and centre
                   as the paper's Fig. 2: -point 0 0 500 -point 512 512 1000.
  -upsample K      Supersample: the sketch's cells (or the peaks') become
                   every K-th cell of a ((W-1)K+1)x((H-1)K+1) grid, the rest
                   is synthesised (the paper's reconstruction of downsampled
                   data): -upsample 8.

Generators (instead of a sketch):
  -skeleton        Ridges and rivers from scratch (Belhadj & Audibert 2005):
                   ridge particle couples, then river particles that run off
                   them, join and drain to the border. Their cells become ridge
                   and river constraints of the terrain.
  -ridge-couples N, -river-particles N   How many (default: about one couple
                   per 80 cells of side, 6 river particles per couple):
                   -ridge-couples 4 -river-particles 40.
  -peaks iizuka|N  Iizuka's multi-peak surface (eq. 8): Table 1's six peaks,
                   or N random ones. Every cell is known; add -upsample K to
                   synthesise detail between them: -peaks iizuka -size 65 65.
  -peaks-noise E   E x GAUSS per cell (default 0; Iizuka's Fig. 5:
                   -peaks-noise -5).
  -peaks-threshold Z   Values below Z become 0 (Iizuka's Z_sh):
                   -peaks-threshold 10.

Synthesis:
  -method m        mcmd (default): the thin plate through the constraints
                   carrying fractal relief, with creases at ridge and river
                   cells. paper (or paper-ds, paper-te): the published MCMD,
                   MDBU then midpoint displacement, on -scheme. mdi: the older
                   bottom-up pass of Belhadj & Audibert 2005, then plain
                   midpoint displacement. none: the constraints alone (unknown
                   cells nodata), e.g. to look at a skeleton. -method paper-te.
  -scheme s        ds (diamond-square, default), te (triangle-edge) or
                   butterfly (the butterfly stencil of Dyn, Levin & Gregory
                   top-down): for -method paper and mdi. -scheme butterfly.
  -rs value|auto   Roughness. A number: a fraction of the constraints'
                   elevation range (-rs 0.5). With m: an amplitude in
                   elevation units, metres on a DEM in metres (-rs 300m),
                   needed from scratch, where there is no range. 0 (default):
                   smooth. For mcmd the amplitude of the coarsest octave, for
                   the paper methods the paper's rs (eq. 1). auto (mcmd): H
                   and amplitude measured from the known cells of a sketch
                   or of a DEM given to -upsample, whose roughness the made
                   detail continues: -upsample 4 -rs auto.
  -H value         Hurst exponent in [0, 1] (default 0.7): high = smooth,
                   rolling relief, low = rugged. The paper's figures: -H 0.45.
  -rt value        Bias in [-1, 1] (default 0): > 0 raises, < 0 lowers the
                   terrain between the constraints: -rt -0.2.
  -seed n          Seed of the relief and the generators (default 0): -seed 7.
                   Same seed, same bits, whatever the thread count.
  -sharpness f     mcmd: how sharp ridge crests and river valleys are, in
                   [0, 10] (default 1; 0 = smooth across them). -sharpness 2.
  -I v, -Ibu v     Paper methods: shape of the top-down and bottom-up
                   interpolation of known cells (the paper's I, I_bu; -100..
                   100). -I 1.1 -Ibu 4.
  -ridge-I v, -ridge-Ibu v, -river-I v, -river-Ibu v   The same for ridge
                   and river cells (default: as known cells): -ridge-I -1.
  -delta form      Paper methods: normalized (default) or paper (Δ as printed):
                   -delta paper.
  -threads n       Worker threads or ALL_CPUS (default): -threads 1.
  -o NAME=VALUE    Any MCMDTerrain option, e.g. -o RIDGE_COUPLES=4.

Erosion (landscape evolution that grows valleys into the terrain; on for
-skeleton, from-scratch and line terrains, off for a sketch, -peaks and
-point; constraint cells never change, rivers keep draining along their
course):
  -erode STEPS|auto|0  Steps on the finest grid (default auto: 8, after the
                   coarsest grid's network has converged; 0: none).
  -erosion K,m,n   Stream-power law E = K A^m S^n: K > 0 or auto (default:
                   the uneroded terrain's relief, its 99th percentile, is
                   kept), m in [0, 2], n in [0.5, 4] (default auto,0.5,1):
                   -erosion auto,0.45,1.
  -uplift terrain|uniform|FILE  Where the land rises: with the uneroded
                   terrain's height (default: its mountains stay), the same
                   everywhere, or a raster of the terrain's size of relative
                   rates >= 0: -uplift uplift.tif.
  -diffusion f     Hillslope creep, a factor of the default (0: none; more:
                   rounder hills, fewer small valleys): -diffusion 2.
  -talus degrees   Slopes steeper than this fail (thermal erosion; default
                   none): -talus 35.

After the synthesis:
  -median N        N x N median filter of the synthesised cells (odd N), as
                   the paper's material example (Fig. 13): -median 5.
  -median-passes P Passes of it (default 1; Fig. 13: -median-passes 2).
  -median-all      Filter the constraint cells too (they then change), as
                   Fig. 13: -median 5 -median-passes 2 -median-all.

Examples:
  mcmd_terrain -size 1025 1025 -rs 300m -seed 4 -hillshade t.png t.tif
  mcmd_terrain -zrange 0 2000 -rs 0.2 -states lines.png sketch.png t.tif
  mcmd_terrain -skeleton -size 513 513 -rs 0.5 -method paper-te -Ibu 6 t.tif
  mcmd_terrain -size 1025 1025 -rs 300m -erode 0 noise_only.tif
  mcmd_terrain -upsample 4 -rs auto coarse_dem.tif fine_dem.tif

Method: F. Belhadj, "Terrain modeling: a constrained fractal model", AFRIGRAPH
2007, pp. 197-204; F. Belhadj, P. Audibert, "Modeling landscapes with ridges
and rivers: bottom up approach", GRAPHITE 2005.
)";
}

}  // namespace mcmd::cli
