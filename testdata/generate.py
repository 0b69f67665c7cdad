#!/usr/bin/python3
"""Regenerate the small GeoTIFFs in testdata/ used by mcmd's tests and README.

Run from anywhere with the system Python (it needs numpy and GDAL's Python
bindings, osgeo.gdal):

    /usr/bin/python3 testdata/generate.py

Every output is a pure function of the constants in this file: random numbers
come from numpy's PCG64 generator with fixed seeds, GDAL writes no timestamps
into GTiff files, and PAM side-car files (.aux.xml) are disabled.  Running the
script twice on the same machine gives byte-identical files.  (Another numpy,
GDAL or zlib build could in principle change the bytes; the committed files are
the reference, and the tests never need Python.)

Terrain
-------
The base relief is the closed-form multi-peak surface of Iizuka (eq. 8 of the
paper in ../shared/seeds/004_*): on a domain 0 <= x, y <= 100 it adds m
"rational" hills  A / (B (x-a)^2 + C (y-b)^2 + D)  and n Gaussian hills
A exp(-(B (x-a)^2 + C (y-b)^2 + D)), with the six parameter rows of the paper's
Table 1 (m = 4, n = 2).  The paper's last term, E * GAUSS, is independent white
noise per grid point; we replace it by spatially correlated detail (spectral
fractional Brownian motion with a fixed seed) so that a void has texture inside
it that a filler can get wrong, rather than pixel noise nobody can predict.
The paper's clipping threshold Z_sh (flattening everything below it to 0) is
not used: flat plains make voids trivial to fill.
"""

import os
import sys

import numpy as np
from osgeo import gdal, osr

gdal.UseExceptions()
# No .aux.xml side-cars (they would carry statistics and break determinism).
gdal.SetConfigOption("GDAL_PAM_ENABLED", "NO")

HERE = os.path.dirname(os.path.abspath(__file__))

# ---------------------------------------------------------------------------
# Terrain
# ---------------------------------------------------------------------------

# Iizuka, Table 1: A, B, C, D, alpha, beta.  Rows 1-4 are the rational hills
# (first sum of eq. 8), rows 5-6 the Gaussian hills (second sum).
RATIONAL_HILLS = [
    (3000.0, 2.0, 6.0, 90.0, 20.0, 90.0),
    (4000.0, 2.0, 4.0, 80.0, 70.0, 80.0),
    (4000.0, 4.0, 2.0, 50.0, 40.0, 80.0),
    (4000.0, 4.0, 2.0, 120.0, 30.0, 20.0),
]
GAUSSIAN_HILLS = [
    (100.0, 0.05, 0.05, 0.0, 20.0, 50.0),
    (50.0, 0.02, 0.02, 0.0, 80.0, 30.0),
]


def multipeak(x, y):
    """Iizuka's eq. 8 without its noise term; x, y in the paper's 0..100 units.

    Returns a dimensionless height of roughly 0..90 for this parameter table.
    """
    z = np.zeros(np.broadcast(x, y).shape, dtype=np.float64)
    for a, b, c, d, alpha, beta in RATIONAL_HILLS:
        z += a / (b * (x - alpha) ** 2 + c * (y - beta) ** 2 + d)
    for a, b, c, d, alpha, beta in GAUSSIAN_HILLS:
        z += a * np.exp(-(b * (x - alpha) ** 2 + c * (y - beta) ** 2 + d))
    return z


def fbm(rows, cols, hurst, seed):
    """Spectral fBm surface of zero mean and unit standard deviation.

    White Gaussian noise is shaped in the Fourier domain by |k|^-(H+1), which
    gives a power spectrum ~ |k|^-(2H+2), the spectrum of a 2-D fBm with Hurst
    exponent H.  The synthesis grid is twice the output size in each direction
    and then cropped, so the output does not wrap around (the FFT surface is
    periodic; the paper notes the same thing about Fourier filtering).
    """
    rng = np.random.Generator(np.random.PCG64(seed))
    pr, pc = 2 * rows, 2 * cols
    white = rng.standard_normal((pr, pc))
    ky = np.fft.fftfreq(pr)[:, None]
    kx = np.fft.rfftfreq(pc)[None, :]
    k = np.sqrt(kx * kx + ky * ky)
    k[0, 0] = 1.0  # avoid division by zero; the mean is removed below anyway
    spectrum = np.fft.rfft2(white) * k ** -(hurst + 1.0)
    spectrum[0, 0] = 0.0
    surf = np.fft.irfft2(spectrum, s=(pr, pc))[:rows, :cols]
    surf -= surf.mean()
    surf /= surf.std()
    return surf


def domain_coords(rows, cols):
    """Map pixel centres onto the paper's 0..100 domain, y pointing north."""
    x = (np.arange(cols) + 0.5) * (100.0 / cols)
    y = 100.0 - (np.arange(rows) + 0.5) * (100.0 / rows)
    return np.meshgrid(x, y)


def quantize(z):
    """Round to 1/1024 m: exactly representable in Float32, and it absorbs
    last-bit differences of exp()/FFT between numpy builds."""
    return np.round(z * 1024.0) / 1024.0


def peaks_terrain(rows, cols):
    """Terrain for the peaks_* files, in metres (about 430..930 m).

    4 m per unit of Iizuka's height keeps the steepest flank near 60 degrees
    at 30 m cells (the paper's narrow hills get very steep if exaggerated)."""
    x, y = domain_coords(rows, cols)
    base = 500.0 + 4.0 * multipeak(x, y)
    detail = 25.0 * fbm(rows, cols, hurst=0.75, seed=20240601)
    return quantize(base + detail)


def sample_terrain(rows, cols):
    """A more natural-looking terrain for the README showcase.

    The multi-peak surface is sampled on a gently warped domain (so the hills
    are not perfect ellipses), then rougher fBm is added at two scales.
    """
    x, y = domain_coords(rows, cols)
    warp_x = 4.0 * fbm(rows, cols, hurst=0.9, seed=11)
    warp_y = 4.0 * fbm(rows, cols, hurst=0.9, seed=12)
    base = 900.0 + 6.0 * multipeak(x + warp_x, y + warp_y)
    regional = 160.0 * fbm(rows, cols, hurst=1.1, seed=13)
    # Ridged component (1 - |fBm|): sharp crests and V-shaped valleys.
    ridged = 120.0 * (1.0 - np.abs(fbm(rows, cols, hurst=1.0, seed=15)))
    rough = fbm(rows, cols, hurst=0.55, seed=14)
    # Rougher where the terrain is higher, as on real mountains.
    rough_amp = 3.0 + 5.0 * (base - base.min()) / (base.max() - base.min())
    return quantize(base + regional + ridged + rough_amp * rough)


# ---------------------------------------------------------------------------
# Voids (boolean masks, True = void)
# ---------------------------------------------------------------------------


def disc(rows, cols, cx, cy, r):
    yy, xx = np.mgrid[0:rows, 0:cols]
    return (xx - cx) ** 2 + (yy - cy) ** 2 <= r * r


def blob(rows, cols, cx, cy, r, seed, wobble=0.35):
    """Irregular star-shaped blob: radius r * (1 + wobble * sum of sines)."""
    rng = np.random.Generator(np.random.PCG64(seed))
    yy, xx = np.mgrid[0:rows, 0:cols]
    dx, dy = xx - cx, yy - cy
    theta = np.arctan2(dy, dx)
    radius = np.ones_like(theta)
    for k in (2, 3, 5):
        amp = rng.uniform(0.3, 1.0) / k
        phase = rng.uniform(0.0, 2.0 * np.pi)
        radius += wobble * amp * np.sin(k * theta + phase)
    return dx * dx + dy * dy <= (r * radius) ** 2


def stripe(rows, cols, x0, y0, x1, y1, half_width):
    """Cells within half_width of the segment (x0, y0)-(x1, y1)."""
    yy, xx = np.mgrid[0:rows, 0:cols].astype(np.float64)
    vx, vy = x1 - x0, y1 - y0
    t = np.clip(((xx - x0) * vx + (yy - y0) * vy) / (vx * vx + vy * vy), 0, 1)
    dist = np.hypot(xx - (x0 + t * vx), yy - (y0 + t * vy))
    return dist <= half_width


def dilate8(mask):
    out = mask.copy()
    padded = np.pad(mask, 1)
    for dy in (-1, 0, 1):
        for dx in (-1, 0, 1):
            out |= padded[1 + dy:1 + dy + mask.shape[0], 1 + dx:1 + dx + mask.shape[1]]
    return out


def single_cells(mask, count, seed, margin=1):
    """Add `count` isolated void cells: none touches another void (8-neighbours).
    margin keeps them off the raster border."""
    rng = np.random.Generator(np.random.PCG64(seed))
    rows, cols = mask.shape
    mask = mask.copy()
    added = 0
    while added < count:
        r = int(rng.integers(margin, rows - margin))
        c = int(rng.integers(margin, cols - margin))
        if dilate8(mask)[r, c]:
            continue
        mask[r, c] = True
        added += 1
    return mask


def peaks_voids(rows, cols):
    """Band-1 voids of the peaks_* files (161 x 123)."""
    m = np.zeros((rows, cols), dtype=bool)
    # Round void over the summit of Table-1 hill (2) (x=70, y=80 -> col 113, row 25):
    # a filler has to rebuild a peak, not just a slope.
    m |= disc(rows, cols, 112.0, 25.0, 9.0)
    # Irregular blob on the flank between the hills.
    m |= blob(rows, cols, 62.0, 70.0, 12.0, seed=101)
    # Smaller irregular blob in the low ground.
    m |= blob(rows, cols, 125.0, 85.0, 6.0, seed=102)
    # A slanted stripe 3 cells wide, like a scan-line gap.
    m |= stripe(rows, cols, 8.0, 112.0, 95.0, 96.0, 1.0)
    # A void touching the right border of the raster.
    m |= blob(rows, cols, 160.0, 55.0, 10.0, seed=103)
    # Isolated single cells.
    m = single_cells(m, 15, seed=104)
    return m


def peaks_voids_band2(rows, cols):
    """Different voids for band 2 of peaks_2band.tif (touching the top border)."""
    m = np.zeros((rows, cols), dtype=bool)
    m |= blob(rows, cols, 35.0, 30.0, 11.0, seed=201)
    m |= disc(rows, cols, 90.0, 100.0, 7.0)
    m |= blob(rows, cols, 140.0, 0.0, 9.0, seed=202)  # touches the top border
    m |= stripe(rows, cols, 20.0, 60.0, 20.0, 118.0, 0.5)  # vertical, 1 cell wide
    m = single_cells(m, 10, seed=203)
    return m


def sample_voids(rows, cols):
    """Voids of the README sample (257 x 257): about 5 % of the area."""
    m = np.zeros((rows, cols), dtype=bool)
    m |= blob(rows, cols, 150.0, 95.0, 24.0, seed=301, wobble=0.45)  # the big one
    m |= blob(rows, cols, 60.0, 60.0, 10.0, seed=302)
    m |= blob(rows, cols, 70.0, 190.0, 12.0, seed=303)
    m |= blob(rows, cols, 200.0, 200.0, 9.0, seed=304)
    m |= blob(rows, cols, 220.0, 40.0, 7.0, seed=305)
    m |= blob(rows, cols, 120.0, 225.0, 6.0, seed=306)
    return m


# ---------------------------------------------------------------------------
# Writing
# ---------------------------------------------------------------------------

UTM11 = 32611
WGS84 = 4326
UTM_GT = (350000.0, 30.0, 0.0, 4110000.0, 0.0, -30.0)  # 30 m, Sierra Nevada area
ARCSEC3 = 3.0 / 3600.0
GEO_GT = (-118.5, ARCSEC3, 0.0, 37.2, 0.0, -ARCSEC3)  # 3 arc-second cells

GDAL_TYPES = {
    np.dtype(np.uint8): gdal.GDT_Byte,
    np.dtype(np.int16): gdal.GDT_Int16,
    np.dtype(np.float32): gdal.GDT_Float32,
}

_NO_NODATA = object()


def srs_wkt(epsg):
    srs = osr.SpatialReference()
    srs.ImportFromEPSG(epsg)
    return srs.ExportToWkt()


def write_tif(name, bands, epsg, geotransform, nodata=_NO_NODATA,
              descriptions=None, metadata=None):
    """Write a DEFLATE-compressed GeoTIFF; bands is a list of 2-D arrays."""
    path = os.path.join(HERE, name)
    dtype = bands[0].dtype
    rows, cols = bands[0].shape
    mem = gdal.GetDriverByName("MEM").Create("", cols, rows, len(bands), GDAL_TYPES[dtype])
    mem.SetGeoTransform(geotransform)
    mem.SetProjection(srs_wkt(epsg))
    for i, arr in enumerate(bands):
        band = mem.GetRasterBand(i + 1)
        band.WriteArray(arr)
        if nodata is not _NO_NODATA:
            band.SetNoDataValue(nodata)
        if descriptions:
            band.SetDescription(descriptions[i])
    if metadata:
        mem.SetMetadata(metadata)
    predictor = "3" if dtype == np.float32 else "2"
    options = ["COMPRESS=DEFLATE", "ZLEVEL=9", "PREDICTOR=" + predictor,
               "INTERLEAVE=BAND"]
    if os.path.exists(path):
        os.remove(path)
    out = gdal.GetDriverByName("GTiff").CreateCopy(path, mem, options=options)
    out = None
    mem = None
    return path


def with_voids(z, mask, fill):
    out = z.copy()
    out[mask] = fill
    return out


def to_int16(z):
    return np.round(z).astype(np.int16)


def main():
    report = []

    # --- peaks: 161 columns x 123 rows -----------------------------------
    rows, cols = 123, 161
    truth = peaks_terrain(rows, cols).astype(np.float32)
    voids = peaks_voids(rows, cols)
    voids2 = peaks_voids_band2(rows, cols)
    truth_i16 = to_int16(truth)

    write_tif("peaks_truth_float32.tif", [truth], UTM11, UTM_GT, nodata=-9999.0)
    report.append(("peaks_truth_float32.tif", 0))

    write_tif("peaks_int16_geo.tif", [with_voids(truth_i16, voids, -32768)],
              WGS84, GEO_GT, nodata=-32768)
    report.append(("peaks_int16_geo.tif", int(voids.sum())))

    write_tif("peaks_float32_utm.tif", [with_voids(truth, voids, -9999.0)],
              UTM11, UTM_GT, nodata=-9999.0)
    report.append(("peaks_float32_utm.tif", int(voids.sum())))

    write_tif("peaks_float32_nan.tif", [with_voids(truth, voids, np.nan)],
              UTM11, UTM_GT, nodata=float("nan"))
    report.append(("peaks_float32_nan.tif", int(voids.sum())))

    # No nodata value at all: void cells hold a plausible but wrong 0; the
    # separate mask file says which cells are valid (255) or void (0).
    write_tif("peaks_nonodata.tif", [with_voids(truth, voids, 0.0)], UTM11, UTM_GT)
    mask = np.where(voids, 0, 255).astype(np.uint8)
    write_tif("peaks_mask.tif", [mask], UTM11, UTM_GT)
    report.append(("peaks_nonodata.tif", int(voids.sum())))
    report.append(("peaks_mask.tif", int(voids.sum())))

    shifted = to_int16(truth.astype(np.float64) + 500.0)
    write_tif("peaks_2band.tif",
              [with_voids(truth_i16, voids, -32768), with_voids(shifted, voids2, -32768)],
              UTM11, UTM_GT, nodata=-32768,
              descriptions=["elevation", "elevation_shifted"],
              metadata={"MCMD_TESTDATA": "peaks_2band: band 2 = band 1 + 500 m, other voids"})
    report.append(("peaks_2band.tif", (int(voids.sum()), int(voids2.sum()))))

    # --- degenerate inputs ------------------------------------------------
    write_tif("all_nodata.tif", [np.full((21, 33), -32768, dtype=np.int16)],
              UTM11, UTM_GT, nodata=-32768)
    report.append(("all_nodata.tif", 21 * 33))
    write_tif("no_nodata.tif", [truth_i16[40:69, 60:101].copy()], UTM11,
              (UTM_GT[0] + 60 * 30.0, 30.0, 0.0, UTM_GT[3] - 40 * 30.0, 0.0, -30.0))
    report.append(("no_nodata.tif", 0))

    # --- README showcase: 257 x 257 ------------------------------------------
    n = 257
    sample = sample_terrain(n, n)
    sample_i16 = to_int16(sample)
    svoids = sample_voids(n, n)
    write_tif("sample_truth.tif", [sample_i16], UTM11, UTM_GT, nodata=-32768)
    write_tif("sample_dem.tif", [with_voids(sample_i16, svoids, -32768)],
              UTM11, UTM_GT, nodata=-32768)
    report.append(("sample_truth.tif", 0))
    report.append(("sample_dem.tif", int(svoids.sum())))

    if "-q" not in sys.argv:
        for name, nvoid in report:
            size = os.path.getsize(os.path.join(HERE, name))
            print(f"{name:26s} {size:8d} bytes  void cells: {nvoid}")
        print(f"sample_dem void fraction: {svoids.mean():.4f}")


if __name__ == "__main__":
    main()
