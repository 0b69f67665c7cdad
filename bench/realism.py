#!/usr/bin/env python3
"""Realism benchmark: mcmd_terrain's terrains against real mountains.

Every entry (from scratch, a sketch, the ridges-and-rivers skeleton, Iizuka's peaks, a real DEM
supersampled) and method is made at 1025 x 1025 cells of 82 m, the size and resolution of the
3-arc-second crops of real DEMs it is scored against, without and with erosion (-erode 0 and
-erode auto). realism_measures.py has the eight measures; each row gives a terrain's value and
its distance to the real crops' range (0 inside it). Also times the erosion (1025^2 to 4097^2,
medians of runs interleaved with the same terrain made without erosion, wall and CPU time, peak
RSS) and draws hillshades side by side with a real crop.

Writes bench/REALISM.md and bench/realism/*.png. Run it with bench/run_realism.sh (--quick:
one timing run, no 4097^2).
"""

from __future__ import annotations

import argparse
import math
import os
import statistics
import subprocess
import sys
import time

import numpy as np
from osgeo import gdal

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(HERE, "terrain"))

import realism_measures as rm  # noqa: E402
import sketches  # noqa: E402

gdal.UseExceptions()
ROOT = os.path.dirname(HERE)
TOOL = os.path.join(ROOT, "build", "bin", "mcmd_terrain")
DEM = os.path.join(ROOT, "..", "shared", "dem")
PICS = os.path.join(HERE, "realism")
WORK = os.path.join(HERE, "work", "realism")
N = 1025
CELL = 82.0  # metres: the 3-arc-second crops' cells at 36-45 N are about 73 x 92 m
GEO = ["-a_srs", "EPSG:32611", "-a_ullr", "400000", "4100000", str(400000 + N * CELL), str(4100000 - N * CELL)]

MOSAIC = "ferranti3_california_nevada_10801x4801.tif"
# 1025^2 crops of real mountains (column, row of their upper-left cell): the mosaic's windows
# whose relief exceeds 1.5 km and which are less than a tenth flat, and the White Mountains.
REAL = [(MOSAIC, 2050, 0, "Klamath Mountains"), (MOSAIC, 3075, 1025, "northern Sierra Nevada"),
        (MOSAIC, 4100, 1025, "Sierra Nevada, Tahoe"), (MOSAIC, 7175, 1025, "Nevada ranges"),
        (MOSAIC, 3075, 2050, "Coast Ranges, Big Sur"), (MOSAIC, 5125, 2050, "Sierra Nevada, Yosemite"),
        (MOSAIC, 9225, 2050, "Nevada basins and ranges"), (MOSAIC, 4100, 3075, "southern Sierra Nevada"),
        (MOSAIC, 6150, 3075, "Owens Valley, White Mountains CA"), (MOSAIC, 9225, 3075, "southern Nevada"),
        ("nasadem3_N44W072_white_mountains.tif", 88, 88, "White Mountains NH")]
SHOWN_REAL = 7  # the southern Sierra Nevada, in the pictures

SCALARS = [("hypsometric", "hypsometric integral", "{:.3f}"), ("spectral", "spectral exponent", "{:.2f}"),
           ("density", "drainage density (km/km²)", "{:.2f}"), ("hack", "Hack exponent", "{:.3f}"),
           ("bifurcation", "bifurcation ratio", "{:.2f}"), ("depressions", "closed depressions /km²", "{:.3f}"),
           ("lattice", "lattice energy", "{:.3f}")]
MEASURES = ["slope"] + [k for k, _, _ in SCALARS]


def read(path):
    return gdal.Open(path).ReadAsArray().astype(np.float64)


def real_crop(name, x0, y0):
    ds = gdal.Open(os.path.join(DEM, name))
    gt = ds.GetGeoTransform()
    lat = gt[3] + gt[5] * (y0 + N / 2)
    z = ds.GetRasterBand(1).ReadAsArray(x0, y0, N, N).astype(np.float64)
    return z, abs(gt[1]) * 111320 * math.cos(math.radians(lat)), abs(gt[5]) * 110574


def hillshade(z, dx, dy, path, size=512):
    """Horn's hillshade, light from the north-west at 45 degrees, reduced to `size` pixels."""
    zp = np.pad(z, 1, mode="edge")
    gx = ((zp[:-2, 2:] + 2 * zp[1:-1, 2:] + zp[2:, 2:]) - (zp[:-2, :-2] + 2 * zp[1:-1, :-2] + zp[2:, :-2])) / (8 * dx)
    gy = ((zp[2:, :-2] + 2 * zp[2:, 1:-1] + zp[2:, 2:]) - (zp[:-2, :-2] + 2 * zp[:-2, 1:-1] + zp[:-2, 2:])) / (8 * dy)
    slope = np.arctan(np.hypot(gx, gy))
    aspect = np.arctan2(gy, -gx)
    az, alt = math.radians(135.0), math.radians(45.0)
    hs = np.clip(math.sin(alt) * np.cos(slope) + math.cos(alt) * np.sin(slope) * np.cos(az - aspect), 0, 1)
    mem = gdal.GetDriverByName("MEM").Create("", z.shape[1], z.shape[0], 1, gdal.GDT_Byte)
    mem.GetRasterBand(1).WriteArray((hs * 255).astype(np.uint8))
    small = gdal.Translate("", mem, format="MEM", width=size, height=size, resampleAlg="average")
    gdal.GetDriverByName("PNG").CreateCopy(path, small)


# The terrains the erosion is judged on, each the median of its measures over these seeds (one seed
# can fall outside a range that the next one meets: the measures vary from terrain to terrain).
SEEDS = {"scratch_mcmd": [4, 14, 24], "skeleton_mcmd": [5, 15, 25]}


def with_seed(args, seed):
    """args with the value after -seed replaced (None: unchanged)."""
    if seed is None:
        return args
    i = args.index("-seed")
    return args[:i + 1] + [str(seed)] + args[i + 2:]


def make(name, args, sketch=None):
    """Run mcmd_terrain into WORK/name.tif; return its heights."""
    out = os.path.join(WORK, name + ".tif")
    cmd = [TOOL, "-q"] + args + ([sketch] if sketch else []) + [out]
    subprocess.run(cmd, check=True)
    return read(out)


def entries():
    """(name, label, arguments, sketch or None) of every entry and method, without erosion."""
    size = ["-size", str(N), str(N)] + GEO
    grey, rgb, _ = sketches.ridges_and_river(N)
    sketch = write_png(os.path.join(WORK, "sketch.png"), grey)
    states = write_png(os.path.join(WORK, "states.png"), rgb)
    coarse = os.path.join(WORK, "coarse.tif")
    z, _, _ = real_crop(*REAL[1][:3])
    write_tif(coarse, z[::4, ::4], 4 * CELL)
    paper = ["-delta", "paper", "-I", "1.0", "-Ibu", "6.0", "-H", "0.49", "-rs", "0.5"]
    skeleton = size + ["-skeleton", "-zrange", "0", "1500", "-seed", "5"]
    drawn = ["-zrange", "0", "6553.5", "-states", states]
    return [
        ("scratch_mcmd", "from scratch, default method", size + ["-rs", "600m", "-seed", "4"], None),
        ("scratch_paper_te", "from scratch, paper te", size + ["-method", "paper-te", "-rs", "1500m", "-H", "0.7",
                                                               "-seed", "4"], None),
        ("scratch_paper_ds", "from scratch, paper ds", size + ["-method", "paper-ds", "-rs", "1500m", "-H", "0.7",
                                                               "-seed", "4"], None),
        ("sketch_mcmd", "sketch, default method", drawn + ["-rs", "150m", "-H", "0.85", "-seed", "3"], sketch),
        ("sketch_paper_te", "sketch, paper te", drawn + ["-method", "paper-te"] + paper, sketch),
        ("skeleton_mcmd", "skeleton, default method", skeleton + ["-rs", "0.1", "-H", "0.85"], None),
        ("skeleton_paper_te", "skeleton, paper te", skeleton + ["-method", "paper-te"] + paper, None),
        ("skeleton_paper_ds", "skeleton, paper ds", skeleton + ["-method", "paper-ds"] + paper, None),
        ("skeleton_mdi", "skeleton, MDI", skeleton + ["-method", "mdi", "-scheme", "te"] + paper, None),
        ("peaks_mcmd", "Iizuka's peaks ×8, default method",
         ["-size", str(N), str(N), "-peaks", "iizuka", "-upsample", "8", "-zrange", "0", "2500", "-rs", "40m"] + GEO,
         None),
        ("upsample_mcmd", "a real DEM ×4, default method", ["-upsample", "4", "-rs", "auto", "-seed", "2"], coarse),
    ]


def write_png(path, array):
    a = array if array.ndim == 3 else array[None]
    dtype = {np.dtype(np.uint8): gdal.GDT_Byte, np.dtype(np.uint16): gdal.GDT_UInt16}[a.dtype]
    mem = gdal.GetDriverByName("MEM").Create("", a.shape[2], a.shape[1], a.shape[0], dtype)
    for b in range(a.shape[0]):
        mem.GetRasterBand(b + 1).WriteArray(a[b])
    gdal.GetDriverByName("PNG").CreateCopy(path, mem)
    return path


def write_tif(path, z, cell):
    ds = gdal.GetDriverByName("GTiff").Create(path, z.shape[1], z.shape[0], 1, gdal.GDT_Float32)
    ds.SetGeoTransform((400000.0, cell, 0.0, 4100000.0, 0.0, -cell))
    srs = gdal.osr.SpatialReference()
    srs.ImportFromEPSG(32611)
    ds.SetProjection(srs.ExportToWkt())
    ds.GetRasterBand(1).WriteArray(z)
    ds = None


# ---- scoring -----------------------------------------------------------------------------

def real_ranges():
    """The real crops' measures: per measure (low, median, high); slope as the Wasserstein
    distance of each crop's slope histogram to the other crops' pooled one."""
    crops = []
    for name, x0, y0, label in REAL:
        z, dx, dy = real_crop(name, x0, y0)
        m = rm.measures(z, dx, dy)
        m["label"], m["z"], m["dx"], m["dy"] = label, z, dx, dy
        crops.append(m)
    pooled = np.mean([c["slope_hist"] for c in crops], axis=0)
    for k, c in enumerate(crops):
        others = np.mean([o["slope_hist"] for j, o in enumerate(crops) if j != k], axis=0)
        c["slope"] = rm.slope_distance(c["slope_hist"], others)
    ranges = {}
    for key in MEASURES:
        values = [c[key] for c in crops]
        ranges[key] = (min(values), statistics.median(values), max(values))
    ranges["slope"] = (0.0, ranges["slope"][1], ranges["slope"][2])
    return crops, ranges, pooled


def distance(value, rng):
    """Outside [low, high]: how far, over the range's width; 0 inside."""
    lo, _, hi = rng
    width = max(hi - lo, 1e-12)
    return max(lo - value, value - hi, 0.0) / width


def near_end(value, rng):
    """Inside the range, or within 10 % of its nearer end's value."""
    lo, _, hi = rng
    return lo * (1 - 0.1 * math.copysign(1, lo)) <= value <= hi * 1.1


def no_farther(a, b, rng):
    """Whether value a is at most as far from the real range as b (both inside: a tie)."""
    return distance(a, rng) <= distance(b, rng)


def closer(a, b, rng):
    """Whether value a is nearer the real crops than b: by the distance to the range, then, both
    inside, by the distance to the real median."""
    da, db = distance(a, rng), distance(b, rng)
    if da != db:
        return da < db
    return abs(a - rng[1]) < abs(b - rng[1])


# ---- timing ------------------------------------------------------------------------------

def timed(args, out):
    """Wall, CPU (user + system) seconds and peak RSS (MB) of one mcmd_terrain run."""
    start = time.perf_counter()
    r = subprocess.run(["/usr/bin/time", "-f", "%U %S %M", TOOL, "-q"] + args + [out], check=True,
                       capture_output=True, text=True)
    wall = time.perf_counter() - start
    user, system, rss = r.stderr.strip().splitlines()[-1].split()
    return wall, float(user) + float(system), int(rss) / 1024.0


def erosion_times(sizes, repeats):
    rows = []
    for n in sizes:
        geo = ["-a_srs", "EPSG:32611", "-a_ullr", "400000", "4100000", str(400000 + n * CELL), str(4100000 - n * CELL)]
        base = ["-size", str(n), str(n), "-rs", "600m", "-seed", "4"] + geo
        runs = {"0": [], "auto": []}
        out = os.path.join(WORK, "timing.tif")
        for _ in range(repeats):
            for erode in ("0", "auto"):  # interleaved
                runs[erode].append(timed(base + ["-erode", erode], out))
        med = {k: [statistics.median(r[i] for r in v) for i in range(3)] for k, v in runs.items()}
        rows.append((n, med["0"], med["auto"]))
    return rows


# ---- report ------------------------------------------------------------------------------

def fmt(key, value):
    if key == "slope":
        return f"{value:.2f}°"
    return dict((k, f) for k, _, f in SCALARS)[key].format(value)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--quick", action="store_true", help="one timing run, no 4097^2")
    args = parser.parse_args()
    os.makedirs(PICS, exist_ok=True)
    os.makedirs(WORK, exist_ok=True)
    crops, ranges, pooled = real_ranges()
    shown = crops[SHOWN_REAL]
    hillshade(shown["z"], shown["dx"], shown["dy"], os.path.join(PICS, "real.png"))

    rows = []
    for name, label, argv, sketch in entries():
        pair = {}
        for erode in ("0", "auto"):
            runs = []
            for k, seed in enumerate(SEEDS.get(name, [None])):
                z = make(f"{name}_{erode}", with_seed(argv, seed) + ["-erode", erode], sketch)
                m = rm.measures(z, CELL, CELL)
                m["slope"] = rm.slope_distance(m["slope_hist"], pooled)
                runs.append(m)
                if k == 0 and name in ("scratch_mcmd", "skeleton_mcmd", "sketch_mcmd", "upsample_mcmd",
                                       "skeleton_paper_te"):
                    hillshade(z, CELL, CELL, os.path.join(PICS, f"{name}_{erode}.png"))
            pair[erode] = {k: statistics.median(r[k] for r in runs) for k in MEASURES}
            pair[erode]["inside_per_seed"] = [sum(near_end(r[k], ranges[k]) for k in MEASURES) for r in runs]
        rows.append((name, label, pair))

    load = os.getloadavg()[0]
    times = erosion_times([513, 1025, 2049] + ([] if args.quick else [4097]), 1 if args.quick else 3)
    write_report(crops, ranges, rows, times, 1 if args.quick else 3, (load, os.getloadavg()[0]))


def write_report(crops, ranges, rows, times, repeats, load):
    md = ["# Realism: synthetic terrains against real mountains", "",
          "`bench/run_realism.sh` (`bench/realism.py`, measures in `bench/realism_measures.py`) makes every "
          "entry and method of `mcmd_terrain` at 1025 × 1025 cells of 82 m, the size and resolution of "
          "3-arc-second crops of real mountains in `../shared/dem`, without erosion (`-erode 0`) and with it "
          "(`-erode auto`), and scores each on eight measures that hydrologists and geomorphologists read off "
          "a DEM. A value is compared with the range of the real crops: its distance to the range, over the "
          "range's width, is 0 inside it.", "",
          "## The real crops", "",
          "| crop | " + " | ".join(label for _, label, _ in SCALARS) + " | slope W₁ to the others |",
          "|---|" + "---|" * (len(SCALARS) + 1)]
    for c in crops:
        md.append(f"| {c['label']} | " + " | ".join(fmt(k, c[k]) for k, _, _ in SCALARS) + f" | {fmt('slope', c['slope'])} |")
    md.append("| **range** | " + " | ".join(f"{fmt(k, ranges[k][0])}–{fmt(k, ranges[k][2])}" for k, _, _ in SCALARS)
              + f" | ≤ {fmt('slope', ranges['slope'][2])} |")
    md += ["", "Measures: slope, the Wasserstein-1 distance (degrees) of the terrain's slope histogram to the "
           "real crops' pooled one (a crop's own: to the other crops'); the hypsometric integral (mean − min) / "
           "(max − min); the spectral exponent β of the radially averaged power spectrum P(k) ∝ k^−β on "
           "wavelengths of 8 cells to a quarter of the raster; the D8 drainage density of channels draining "
           "1 km² or more; Hack's exponent h in L ∝ A^h (longest flow path above a channel cell against its "
           "area); Horton's bifurcation ratio from the Strahler orders; closed depressions deeper than 1 m per "
           "km²; the lattice energy, the largest departure from 1 of the Laplacian's energy on the rows and "
           "columns that are multiples of 2^k (k = 1 … 5) over their share of the cells.", "",
           "## Every entry and method, without and with erosion", "",
           "Each cell: the value, and in brackets its distance to the real range when outside it. **in**: "
           "measures inside the range or within 10 % of its nearer end; **closer**: measures on which the eroded "
           "terrain is nearer the real crops than the uneroded one (by the distance to the range, then, both "
           "inside, by the distance to the real median); **no farther**: measures on which the eroded terrain "
           "is at most as far from the range as the uneroded one (both inside counts). The default method from scratch and from a skeleton "
           "are medians over three seeds (each measure's median; in brackets how many measures each seed has "
           "in range); the other rows are one terrain each.", "",
           "| terrain | erosion | " + " | ".join(["slope W₁"] + [label for _, label, _ in SCALARS]) + " | in | closer | no farther |",
           "|---|---|" + "---|" * (len(MEASURES) + 3)]
    for name, label, pair in rows:
        for erode in ("0", "auto"):
            m = pair[erode]
            cells = []
            inside = 0
            for k in MEASURES:
                d = distance(m[k], ranges[k])
                inside += near_end(m[k], ranges[k])
                cells.append(fmt(k, m[k]) + (f" ({d:.2f})" if d > 0 else ""))
            eroded = erode == "auto"
            better = sum(closer(pair["auto"][k], pair["0"][k], ranges[k]) for k in MEASURES) if eroded else ""
            kept = sum(no_farther(pair["auto"][k], pair["0"][k], ranges[k]) for k in MEASURES) if eroded else ""
            seeds = m["inside_per_seed"]
            per_seed = f" (seeds: {', '.join(map(str, seeds))})" if len(seeds) > 1 else ""
            md.append(f"| {label} | {'auto' if erode == 'auto' else 'none'} | " + " | ".join(cells)
                      + f" | {inside}/8{per_seed} | {better}{'/8' if eroded else ''} | {kept}{'/8' if eroded else ''} |")
    md += ["", "## Hillshades", "",
           "1025 × 1025 cells of 82 m (84 km across), reduced to 512 pixels, light from the north-west; "
           "left a real crop (the southern Sierra Nevada), then the terrain without and with erosion.", "",
           "| real | without erosion | with erosion | |", "|---|---|---|---|"]
    for name, label in (("skeleton_mcmd", "skeleton, default method"), ("scratch_mcmd", "from scratch, default method"),
                        ("skeleton_paper_te", "skeleton, paper te"), ("sketch_mcmd", "sketch, default method"),
                        ("upsample_mcmd", "a real DEM ×4, default method")):
        md.append(f"| ![real](realism/real.png) | ![{label}](realism/{name}_0.png) | ![{label}, eroded]"
                  f"(realism/{name}_auto.png) | {label} |")
    md += ["", "## Erosion time and memory", "",
           f"`mcmd_terrain -size N N -rs 600m` with `-erode auto` against `-erode 0` (the same terrain, not "
           f"eroded), medians of {repeats} interleaved runs each: wall and CPU seconds, peak RSS. Erosion = "
           "the difference.", "",
           f"Load average {load[0]:.1f} when the timings began, {load[1]:.1f} when they ended (2 cores, shared).", "",
           "| size | cells | wall, no erosion | wall, eroded | erosion wall | erosion CPU | peak RSS, eroded | RSS per cell |",
           "|---|---|---|---|---|---|---|---|"]
    for n, off, on in times:
        md.append(f"| {n}² | {n * n / 1e6:.2f} M | {off[0]:.2f} s | {on[0]:.2f} s | {on[0] - off[0]:.2f} s | "
                  f"{on[1] - off[1]:.2f} s | {on[2]:.0f} MB | {on[2] * 1e6 / (n * n):.0f} B |")
    with open(os.path.join(HERE, "realism_reading.md")) as f:  # written by hand, from the pictures
        md += ["", f.read().rstrip()]
    with open(os.path.join(HERE, "REALISM.md"), "w") as f:
        f.write("\n".join(md) + "\n")


if __name__ == "__main__":
    main()
