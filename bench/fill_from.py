#!/usr/bin/python3
"""Delta surface fill benchmark: -fill-from against the plain fill and the second DEM alone.

The accuracy benchmark's void-free DEMs with blob voids (3 seeds) are filled
three ways: the plain default, `-fill-from COARSE` where COARSE is the truth
averaged to 10x coarser cells (a stand-in for a GTOPO30-like product over an
SRTM tile), and COARSE alone (cubic-resampled onto the grid, GDAL's warp).
RMSE over the voids, and the rim step: the mean |fill - known neighbour| over
the 4-neighbour pairs across the void rims, divided by the truth's mean over
the same pairs (1: no step). The real-void SRTM tiles are filled from
themselves averaged 10x (coarse cells ignore the voids; no truth: the rim step
is divided by the mean known-known neighbour difference around the voids).
Writes bench/FILL_FROM.md and hillshades of the largest void in bench/fill_from/.

    /usr/bin/python3 bench/fill_from.py [--mcmd build/bin/mcmd_fillnodata] [--quick]
"""
from __future__ import annotations

import os
import subprocess
import sys
import time

import numpy as np
from osgeo import gdal

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import accuracy as A  # noqa: E402
import voids as V  # noqa: E402

gdal.UseExceptions()
FACTOR = 10


def parse_args(argv=None):
    ap = V.common_parser(__doc__, "1 DEM, 1 seed, 1 real tile; writes bench/work/FILL_FROM-quick.md",
                         "restrict to DEMs whose name contains this (repeatable)")
    ap.add_argument("--seeds", type=int, default=3)
    a = ap.parse_args(argv)
    a.dems = list(A.TRUTH_DEMS)
    a.reals = list(A.REAL_DEMS)
    if a.quick:
        a.seeds, a.dems, a.reals = 1, ["nasadem3_mt_washington_513"], ["srtm3_N43E007_alpes_maritimes_voids"]
    if a.only:
        a.dems = [d for d in a.dems if any(o in d for o in a.only)]
        a.reals = [d for d in a.reals if any(o in d for o in a.only)]
    a.work = os.path.join(V.BENCH_DIR, "work", "fill_from" + ("-quick" if a.quick else ""))
    a.out = os.path.join(V.BENCH_DIR, "work", "FILL_FROM-quick.md") if a.quick else \
        os.path.join(V.BENCH_DIR, "FILL_FROM.md")
    a.png_dir = os.path.join(V.BENCH_DIR, "work" if a.quick else "", "fill_from")
    a.mcmd = os.path.abspath(a.mcmd)
    return a


def coarse_of(src: str, dst: str):
    """src averaged to FACTOR-times coarser cells (voids ignored), same extent."""
    if not os.path.exists(dst):
        ds = gdal.Open(src)
        gdal.Translate(dst, ds, width=max(2, ds.RasterXSize // FACTOR), height=max(2, ds.RasterYSize // FACTOR),
                       resampleAlg="average", outputType=gdal.GDT_Float32)


def alone(coarse: str, like: str, dst: str):
    """coarse cubic-resampled onto like's grid."""
    ds = gdal.Open(like)
    g = ds.GetGeoTransform()
    bounds = (g[0], g[3] + g[5] * ds.RasterYSize, g[0] + g[1] * ds.RasterXSize, g[3])
    gdal.Warp(dst, coarse, width=ds.RasterXSize, height=ds.RasterYSize, outputBounds=bounds,
              dstSRS=ds.GetProjection(), resampleAlg="cubic", outputType=gdal.GDT_Float64)


def rim_pairs(removed: np.ndarray):
    """(void y, void x, known y, known x): 4-neighbours across the void rims."""
    h, w = removed.shape
    parts = [[], [], [], []]
    vy, vx = np.nonzero(removed)
    for dy, dx in ((0, 1), (0, -1), (1, 0), (-1, 0)):
        ny, nx = vy + dy, vx + dx
        ok = (ny >= 0) & (ny < h) & (nx >= 0) & (nx < w)
        ok[ok] = ~removed[ny[ok], nx[ok]]
        for part, arr in zip(parts, (vy[ok], vx[ok], ny[ok], nx[ok])):
            part.append(arr)
    return [np.concatenate(p) for p in parts]


def rim_step(fill: np.ndarray, pairs) -> float:
    vy, vx, ky, kx = pairs
    return float(np.mean(np.abs(fill[vy, vx] - fill[ky, kx])))


def known_step(z: np.ndarray, removed: np.ndarray) -> float:
    """Mean |difference| of known 4-neighbours within 5 cells of a void."""
    near = np.zeros_like(removed)
    for dy in range(-5, 6):
        for dx in range(-5, 6):
            near |= np.roll(np.roll(removed, dy, 0), dx, 1)
    k = ~removed
    a = np.abs(np.diff(z, axis=1))[(k[:, 1:] & k[:, :-1] & near[:, 1:])]
    return float(np.mean(a))


def read(path):
    return gdal.Open(path).ReadAsArray().astype(np.float64)


def timed(cmd) -> float:
    t = time.perf_counter()
    subprocess.run(cmd, check=True)
    return time.perf_counter() - t


def hillshade_row(stem: str, paths, removed: np.ndarray, png_dir: str, geographic: bool):
    """Hillshades of the window around the largest void of each path, side by side."""
    from scipy import ndimage
    lab, n = ndimage.label(removed)
    if n == 0:
        return None
    big = np.argmax(np.bincount(lab.ravel())[1:]) + 1
    ys, xs = np.nonzero(lab == big)
    pad = 40
    y0, y1 = max(0, ys.min() - pad), min(removed.shape[0], ys.max() + pad)
    x0, x1 = max(0, xs.min() - pad), min(removed.shape[1], xs.max() + pad)
    tiles = []
    for p in paths:
        crop = gdal.Translate("", p, format="MEM", srcWin=[int(x0), int(y0), int(x1 - x0), int(y1 - y0)])
        hs = gdal.DEMProcessing("", crop, "hillshade", format="MEM", computeEdges=True,
                                scale=111120 if geographic else 1)
        tiles.append(hs.ReadAsArray())
    gap = np.full((tiles[0].shape[0], 6), 255, np.uint8)
    row = np.concatenate([t for tile in tiles for t in (tile, gap)][:-1], axis=1)
    os.makedirs(png_dir, exist_ok=True)
    out = os.path.join(png_dir, stem + ".png")
    mem = gdal.GetDriverByName("MEM").Create("", row.shape[1], row.shape[0], 1, gdal.GDT_Byte)
    mem.GetRasterBand(1).WriteArray(row)
    gdal.GetDriverByName("PNG").CreateCopy(out, mem)
    return os.path.relpath(out, os.path.dirname(os.path.abspath(__file__)))


def main(argv=None):
    a = parse_args(argv)
    work = a.work
    V.make_work_dirs(work)
    rows, reals, pngs = [], [], {}
    for dem in a.dems:
        truth_path = A.truth_path(dem, work)
        truth = read(truth_path)
        coarse = os.path.join(work, "inputs", dem + "__coarse.tif")
        coarse_of(truth_path, coarse)
        second = os.path.join(work, "out", dem + "__alone.tif")
        alone(coarse, truth_path, second)
        geographic = V.is_geographic(truth_path)
        for seed in range(a.seeds):
            cid = f"{dem}__blobs__s{seed}"
            inp = os.path.join(work, "inputs", cid + ".tif")
            V.make_voided(truth_path, inp, "blobs", seed)
            removed = ~V.read_raster(inp).valid()
            plain, delta = (os.path.join(work, "out", f"{cid}__{m}.tif") for m in ("plain", "fill-from"))
            t_plain = timed([a.mcmd, "-q", inp, plain])
            t_delta = timed([a.mcmd, "-q", "-fill-from", coarse, inp, delta])
            pairs = rim_pairs(removed)
            truth_step = rim_step(truth, pairs)
            r = {"case": cid, "t_plain": t_plain, "t_delta": t_delta}
            for key, path in (("plain", plain), ("delta", delta), ("alone", second)):
                f = read(path)
                if key == "alone":
                    f = np.where(removed, f, truth)  # the second DEM inside the voids only
                r[key] = float(np.sqrt(np.mean((f[removed] - truth[removed]) ** 2)))
                r["step_" + key] = rim_step(f, pairs) / truth_step
            rows.append(r)
            V.log(f"{cid}: plain {r['plain']:.1f} m, fill-from {r['delta']:.1f} m, alone {r['alone']:.1f} m")
            if seed == 0:
                pngs[dem] = hillshade_row(dem, [inp, plain, delta, truth_path], removed, a.png_dir, geographic)
    for dem in a.reals:
        src = os.path.join(V.DEM_DIR, dem + ".tif")
        coarse = os.path.join(work, "inputs", dem + "__coarse.tif")
        coarse_of(src, coarse)
        inr = V.read_raster(src)
        removed = ~inr.valid()
        plain, delta = (os.path.join(work, "out", f"{dem}__{m}.tif") for m in ("plain", "fill-from"))
        t_plain = timed([a.mcmd, "-q", src, plain])
        t_delta = timed([a.mcmd, "-q", "-fill-from", coarse, src, delta])
        pairs = rim_pairs(removed)
        base = known_step(inr.data.astype(np.float64), removed)
        reals.append({"case": dem, "t_plain": t_plain, "t_delta": t_delta,
                      "step_plain": rim_step(read(plain), pairs) / base,
                      "step_delta": rim_step(read(delta), pairs) / base})
        pngs[dem] = hillshade_row(dem, [src, plain, delta], removed, a.png_dir, True)
    write_report(a, rows, reals, pngs)
    V.log(f"wrote {a.out}")


def write_report(a, rows, reals, pngs):
    med = lambda k: float(np.median([r[k] for r in rows]))  # noqa: E731
    ratio = lambda k: float(np.median([r[k] / r["plain"] for r in rows]))  # noqa: E731
    L = ["# Delta surface fill: `-fill-from` a coarser DEM", "",
         "Made by `bench/run_fill_from.sh` (`bench/fill_from.py`, its docstring says how). "
         f"Machine: {V.machine_info()}.", "",
         f"Blob voids (~5 % of the area, 3 seeds) in {len(a.dems)} void-free DEMs. The second DEM is the truth "
         f"averaged to {FACTOR}x coarser cells; *alone* is that DEM cubic-resampled into the voids. "
         "RMSE over the void cells; *rim step* = mean |fill − known neighbour| across the void rims ÷ the "
         "truth's (1 = as smooth as the terrain, more = a step). Times are whole runs of the CLI.", "",
         "## Medians", "",
         "| fill | RMSE m | RMSE ÷ plain | worst ÷ plain | rim step | time s |",
         "|---|---|---|---|---|---|"]
    for key, name, t in (("plain", "plain default", "t_plain"), ("delta", "`-fill-from`", "t_delta"),
                         ("alone", "second DEM alone", None)):
        worst = max(r[key] / r["plain"] for r in rows)
        L.append(f"| {name} | {med(key):.1f} | {ratio(key):.3f} | {worst:.3f} | {med('step_' + key):.2f} | "
                 f"{med(t) if t else float('nan'):.2f} |".replace("| nan |", "| — |"))
    below = sum(r["delta"] < r["alone"] for r in rows)
    L += ["", f"`-fill-from` is below the second DEM alone on {below} of {len(rows)} cases.", "",
          "## Cases", "", "| case | plain m | fill-from m (÷ plain) | alone m (÷ plain) | rim step fill-from / alone |",
          "|---|---|---|---|---|"]
    for r in rows:
        L.append(f"| {r['case']} | {r['plain']:.1f} | {r['delta']:.1f} ({r['delta'] / r['plain']:.2f}) | "
                 f"{r['alone']:.1f} ({r['alone'] / r['plain']:.2f}) | {r['step_delta']:.2f} / {r['step_alone']:.2f} |")
    if reals:
        L += ["", "## Real voids (no truth)", "",
              f"SRTM tiles with real voids, filled from themselves averaged {FACTOR}x (coarse cells average the "
              "known cells they hold). Rim step ÷ the mean difference of known neighbours near the voids.", "",
              "| tile | rim step plain | rim step fill-from | time plain s | time fill-from s |", "|---|---|---|---|---|"]
        for r in reals:
            L.append(f"| {r['case']} | {r['step_plain']:.2f} | {r['step_delta']:.2f} | {r['t_plain']:.2f} | "
                     f"{r['t_delta']:.2f} |")
    L += ["", "## The largest void of each DEM (seed 0)", "",
          "Hillshades, left to right: the input, the plain fill, `-fill-from`, the truth (real tiles: input, "
          "plain, `-fill-from`).", ""]
    for dem, png in pngs.items():
        if png:
            L += [f"**{dem}**", "", f"![]({png})", ""]
    with open(a.out, "w") as f:
        f.write("\n".join(L) + "\n")


if __name__ == "__main__":
    sys.exit(main())
