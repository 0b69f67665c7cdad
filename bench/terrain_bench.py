#!/usr/bin/env python3
"""Terrain benchmark: the MCMD paper's terrain figures regenerated with mcmd_terrain, the
acceptance checks on a sketch, MDI against MCMD, and whole-process times against the paper's.

Writes bench/TERRAIN.md and bench/terrain/*.png (hillshades, 384 px). Inputs are drawn here
(bench/terrain/sketches.py) and the Mount Washington DEM is read from ../shared/dem. Run it
with bench/run_terrain.sh on a quiet machine; --quick times one run instead of the best of five.
"""

from __future__ import annotations

import argparse
import os
import subprocess
import sys
import time

import numpy as np
from osgeo import gdal

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(HERE, "terrain"))

import checks  # noqa: E402
import sketches  # noqa: E402
import voids  # noqa: E402

gdal.UseExceptions()
ROOT = os.path.dirname(HERE)
TOOL = os.path.join(ROOT, "build", "bin", "mcmd_terrain")
PICS = os.path.join(HERE, "terrain")
WORK = os.path.join(HERE, "work", "terrain")
PNG = 384


def write(path, array, driver="PNG", bands=None):
    """A numpy array (2-D, or bands x rows x cols) as an image."""
    a = array if array.ndim == 3 else array[None]
    dtype = {np.dtype(np.uint8): gdal.GDT_Byte, np.dtype(np.uint16): gdal.GDT_UInt16}[a.dtype]
    mem = gdal.GetDriverByName("MEM").Create("", a.shape[2], a.shape[1], a.shape[0], dtype)
    for b in range(a.shape[0]):
        mem.GetRasterBand(b + 1).WriteArray(a[b])
    gdal.GetDriverByName(driver).CreateCopy(path, mem)
    return path


def read(path):
    return gdal.Open(path).ReadAsArray().astype(np.float64)


class Runner:
    def __init__(self, repeats: int):
        self.repeats = repeats

    def terrain(self, name: str, args: list[str], sketch: str | None = None, picture: bool = True,
                timed: bool = False) -> dict:
        """Run mcmd_terrain into WORK/name.tif; the best wall time of `repeats` runs when timed;
        its hillshade reduced to bench/terrain/name.png when `picture`."""
        out = os.path.join(WORK, name + ".tif")
        cmd = [TOOL, "-q"] + args + ([sketch] if sketch else []) + [out]
        best = None
        for _ in range(self.repeats if timed else 1):
            t0 = time.perf_counter()
            subprocess.run(cmd, check=True)
            dt = time.perf_counter() - t0
            best = dt if best is None else min(best, dt)
        if picture:
            full = os.path.join(WORK, name + "_hs.png")
            subprocess.run(cmd[:-1] + ["-hillshade", full, out], check=True)
            gdal.Translate(os.path.join(PICS, name + ".png"), full, width=PNG, height=0, resampleAlg="average")
        return {"out": out, "seconds": best, "z": read(out)}


def f(x, spec=".2f"):
    return "—" if x is None else format(x, spec)


def figure_2_and_3(run: Runner, md: list):
    n = 257
    pts = sketches.five_points(n)
    md += ["## Fig. 2 and 3: five constraints", "",
           "Corners at 500, the centre at 1000, 257×257, the paper's triangle-edge (te) and "
           "diamond-square (ds) top-down schemes, without and with noise (`-rs 0.25 -H 0.5`), and "
           "the default method (mcmd, `-rs 0.25 -H 0.85`: its rs is the amplitude of its coarsest octave, a fraction of the constraints' range).", ""]
    cells = []
    for scheme in ("te", "ds"):
        for rs in ("0", "0.25"):
            name = f"fig2_{scheme}_rs{rs}"
            run.terrain(name, ["-size", str(n), str(n), "-method", "paper", "-scheme", scheme, "-delta", "paper", "-rs", rs,
                               "-H", "0.5", "-seed", "1"] + pts)
            cells.append(f"![{name}](terrain/{name}.png)")
    run.terrain("fig2_mcmd", ["-size", str(n), str(n), "-rs", "0.25", "-H", "0.85", "-seed", "1"] + pts)
    md += ["| te | te + noise | ds | ds + noise |", "|---|---|---|---|", "| " + " | ".join(cells) + " |", "",
           "Default method: ![fig2_mcmd](terrain/fig2_mcmd.png)", ""]
    variants = [("a", "-0.4", "0.5", "0", "0"), ("b", "-0.4", "0.5", "0", "0.25"), ("c", "-0.4", "0.5", "-1", "0.25"),
                ("d", "0.4", "0.4", "0", "0"), ("e", "0.4", "0.4", "0", "0.15"), ("f", "0.4", "0.4", "1", "0.15"),
                ("g", "-2", "0.5", "-0.9", "0.55"), ("h", "2", "0.5", "-0.5", "0.6")]
    md += ["Fig. 3's parameter grid, triangle-edge on the same constraints:", "",
           "| | I | H | rt | rs | |", "|---|---|---|---|---|---|"]
    for tag, i, h, rt, rs in variants:
        name = f"fig3_{tag}"
        run.terrain(name, ["-size", str(n), str(n), "-method", "paper-te", "-delta", "paper", "-I", i, "-H", h, "-rt", rt,
                           "-rs", rs, "-seed", "1"] + pts)
        md.append(f"| ({tag}) | {i} | {h} | {rt} | {rs} | ![{name}](terrain/{name}.png) |")
    md.append("")


def figure_8(run: Runner, md: list):
    n = 513
    path = write(os.path.join(WORK, "circle.png"), sketches.circle_and_segments(n))
    b = run.terrain("fig8_b", ["-method", "paper-te", "-delta", "paper", "-Ibu", "6", "-I", "1"], path)
    d = run.terrain("fig8_d", ["-method", "paper-te", "-delta", "paper", "-Ibu", "5", "-I", "-0.7", "-H", "0.4", "-rt", "-1",
                               "-rs", "0.2", "-seed", "2"], path)
    m = run.terrain("fig8_mcmd", ["-rs", "0.05", "-H", "0.8", "-seed", "2"], path)
    md += ["## Fig. 8: a circle and four segments", "",
           "The circle at 230, the diagonal segments at 120, the bottom-left one shifted a cell "
           "(Byte sketch, 513×513). MDBU then triangle-edge MD: (b) `-Ibu 6 -I 1`, (d) `-Ibu 5 -I -0.7 "
           "-H 0.4 -rt -1 -rs 0.2`; the default method with `-rs 0.05 -H 0.8`. Lattice energy: "
           "the Laplacian's energy on the rows and columns that are multiples of 32 over their "
           "share of the cells (1 = none of the subdivision's lattice shows).", "",
           "| (b) | (d) | default method |", "|---|---|---|",
           "| ![b](terrain/fig8_b.png) | ![d](terrain/fig8_d.png) | ![m](terrain/fig8_mcmd.png) |",
           f"| lattice {checks.grid_streaks(b['z']):.2f} | lattice {checks.grid_streaks(d['z']):.2f} | "
           f"lattice {checks.grid_streaks(m['z']):.2f} |", ""]


def skeleton_figures(run: Runner, md: list, times: dict):
    n = 513
    size = ["-size", str(n), str(n), "-skeleton", "-seed", "5"]
    none = run.terrain("skeleton_dem", size + ["-method", "none"], picture=False)
    write(os.path.join(PICS, "skeleton_dem.png"), np.where(np.isnan(none["z"]), 255, 0).astype(np.uint8))
    # The paper's figure is not eroded: -erode 0 (erosion is on by default around a skeleton).
    paper = ["-delta", "paper", "-I", "1.0", "-Ibu", "6.0", "-H", "0.49", "-rt", "0.0", "-rs", "0.5", "-erode", "0"]
    te = run.terrain("fig11a_te", size + ["-method", "paper-te"] + paper, timed=True)
    ds = run.terrain("fig11a_ds", size + ["-method", "paper-ds"] + paper, timed=True)
    bf = run.terrain("fig11a_butterfly", size + ["-method", "paper", "-scheme", "butterfly"] + paper, timed=True)
    mdi = run.terrain("fig11a_mdi", size + ["-method", "mdi", "-scheme", "te"] + paper, timed=True)
    mc = run.terrain("fig11a_mcmd", size + ["-rs", "0.1", "-H", "0.85", "-erode", "0"], timed=True)
    me = run.terrain("fig11a_mcmd_eroded", size + ["-rs", "0.1", "-H", "0.85"], timed=True)
    times["skeleton"] = {"te": te["seconds"], "ds": ds["seconds"], "mcmd": mc["seconds"], "mdi": mdi["seconds"],
                         "butterfly": bf["seconds"], "eroded": me["seconds"]}
    md += ["## Fig. 11(a): around a ridges-and-rivers skeleton", "",
           "`-skeleton` on 513×513 (seed 5): ridge particle couples, river particles that join "
           "and drain to the border (left: the skeleton DEM, `-method none`, ridge and river cells "
           "black). The paper's parameters `-I 1.0 -Ibu 6.0 -H 0.49 -rt 0 -rs 0.5` with each "
           "top-down scheme and MDI, and the default method with `-rs 0.1 -H 0.85`, all without erosion "
           "(`-erode 0`, as the paper); last, the default method as `mcmd_terrain` makes it, eroded "
           "(docs/terrain.md, bench/REALISM.md).", "",
           "| skeleton | paper te | paper ds | butterfly | MDI | default method | default method, eroded |",
           "|---|---|---|---|---|---|---|",
           "| ![s](terrain/skeleton_dem.png) | ![te](terrain/fig11a_te.png) | ![ds](terrain/fig11a_ds.png) | "
           "![bf](terrain/fig11a_butterfly.png) | ![mdi](terrain/fig11a_mdi.png) | ![m](terrain/fig11a_mcmd.png) | "
           "![e](terrain/fig11a_mcmd_eroded.png) |",
           "| | " + " | ".join(f"lattice {checks.grid_streaks(r['z']):.2f}" for r in (te, ds, bf, mdi, mc, me)) + " |", ""]
    path = write(os.path.join(WORK, "lsystem.png"), sketches.lsystem_sketch(n))
    ls = run.terrain("fig11b_te", ["-method", "paper-te", "-delta", "paper", "-I", "1.1", "-Ibu", "10.0", "-H", "0.48", "-rt", "0",
                                   "-rs", "0.5", "-seed", "3"], path, timed=True)
    lm = run.terrain("fig11b_mcmd", ["-rs", "0.1", "-H", "0.85", "-seed", "3"], path)
    times["lsystem"] = {"te": ls["seconds"]}
    md += ["## Fig. 11(b): around a bracketed L-system", "",
           "The footnote's L-system drawn into a Byte sketch (the trunk high, the branches "
           "lower), `-I 1.1 -Ibu 10 -H 0.48 -rs 0.5` with triangle-edge, and the default method.", "",
           "| paper te | default method |", "|---|---|",
           "| ![l](terrain/fig11b_te.png) | ![l](terrain/fig11b_mcmd.png) |", ""]


def figure_12_and_13(run: Runner, md: list, times: dict):
    n = 1025
    path = write(os.path.join(WORK, "africa.png"), sketches.africa_sketch(n))
    a = ["-delta", "paper", "-I", "-1.1", "-Ibu", "-20.0", "-H", "0.45", "-rt", "-0.2", "-rs", "1.0"]
    b = ["-delta", "paper", "-I", "1.1", "-Ibu", "4.0", "-H", "0.45", "-rt", "0.0", "-rs", "1.1"]
    runs = {}
    for tag, params in (("a", a), ("b", b)):
        for scheme in ("te", "ds"):
            runs[tag + scheme] = run.terrain(f"fig12{tag}_{scheme}", ["-method", "paper-" + scheme] + params, path,
                                             timed=True)
    mc = run.terrain("fig12_mcmd", ["-rs", "0.1", "-H", "0.85", "-seed", "1"], path, timed=True)
    times["sketch"] = {"te": min(runs["ate"]["seconds"], runs["bte"]["seconds"]),
                       "ds": min(runs["ads"]["seconds"], runs["bds"]["seconds"]), "mcmd": mc["seconds"]}
    md += ["## Fig. 12: around a sketch", "",
           "The Africa silhouette (grey 200) and \"Afrigraph '07\" (grey 70) in a 1025×1025 Byte image, its border at 10, white unknown. "
           "(a) `-I -1.1 -Ibu -20 -H 0.45 -rt -0.2 -rs 1.0`, (b) `-I 1.1 -Ibu 4 -H 0.45 -rs 1.1`, "
           "each with both schemes; the default method with `-rs 0.1 -H 0.85`.", "",
           "| (a) te | (a) ds | (b) te | (b) ds | default method |", "|---|---|---|---|---|",
           "| ![](terrain/fig12a_te.png) | ![](terrain/fig12a_ds.png) | ![](terrain/fig12b_te.png) | "
           "![](terrain/fig12b_ds.png) | ![](terrain/fig12_mcmd.png) |",
           "| " + " | ".join(f"lattice {checks.grid_streaks(runs[k]['z']):.2f}" for k in ("ate", "ads", "bte", "bds"))
           + f" | lattice {checks.grid_streaks(mc['z']):.2f} |", ""]
    path = write(os.path.join(WORK, "material.png"), sketches.material_sketch(n))
    params = ["-delta", "paper", "-I", "3.0", "-Ibu", "7.5", "-H", "0.5", "-rt", "0.1", "-rs", "1.3"]
    raw = run.terrain("fig13_raw", ["-method", "paper-te"] + params, path, timed=True)
    med = run.terrain("fig13_median", ["-method", "paper-te"] + params + ["-median", "5", "-median-passes", "2",
                                                                         "-median-all"], path, timed=True)
    times["material"] = {"te": med["seconds"], "raw": raw["seconds"]}
    md += ["## Fig. 13: material modelling", "",
           "1 % of random grey pixels, the silhouette and the text (1025×1025), triangle-edge with "
           "`-I 3 -Ibu 7.5 -H 0.5 -rt 0.1 -rs 1.3`, then two passes of a 5×5 median over every cell "
           "(`-median 5 -median-passes 2 -median-all`).", "",
           "| MCMD | + median |", "|---|---|", "| ![](terrain/fig13_raw.png) | ![](terrain/fig13_median.png) |", ""]


def acceptance(run: Runner, md: list, times: dict):
    n = 513
    grey, rgb, traced = sketches.ridges_and_river(n)
    sketch = write(os.path.join(WORK, "ridges_river.png"), grey)
    states = write(os.path.join(WORK, "ridges_river_states.png"), rgb)
    base = ["-zrange", "0", "6553.5", "-states", states]
    cases = [("default method", "sketch_mcmd", ["-rs", "150m", "-H", "0.85", "-seed", "3"]),
             ("paper ds", "sketch_ds", ["-method", "paper-ds", "-delta", "paper", "-I", "1.1", "-Ibu", "4", "-H", "0.45", "-rs", "0.5"]),
             ("paper te", "sketch_te", ["-method", "paper-te", "-delta", "paper", "-I", "1.1", "-Ibu", "4", "-H", "0.45", "-rs", "0.5"]),
             ("butterfly", "sketch_butterfly", ["-method", "paper", "-scheme", "butterfly", "-delta", "paper", "-I", "1.1", "-Ibu", "4",
                                                "-H", "0.45", "-rs", "0.5"]),
             ("MDI", "sketch_mdi", ["-method", "mdi", "-scheme", "te", "-H", "0.45", "-rs", "0.5"])]
    md += ["## The acceptance sketch: two ridges and a river", "",
           "A 513×513 UInt16 sketch (grey = 10 × elevation: ridges 840–940, the river from 480 at its "
           "source down to 80 at the right border, every other cell white) and a states image (ridges "
           "red, the river blue), `-zrange 0 6553.5 -states states.png`. Ridge maxima: the share of "
           "ridge cells higher than both cells 1.5 cells away across the line. River: whether the D8 "
           "path from the river's source reaches the border, and the share of its cells on the river.", "",
           "| method | options | ridge maxima | D8 reaches the border | D8 cells on the river | lattice | |",
           "|---|---|---|---|---|---|---|"]
    for label, name, args in cases:
        r = run.terrain(name, base + args, sketch, timed=name == "sketch_mcmd")
        c = checks.sketch_checks(r["z"], traced)
        md.append(f"| {label} | `{' '.join(args)}` | {c['ridge_maxima']:.1%} | {'yes' if c['river_to_border'] else 'no'} "
                  f"| {c['river_share']:.1%} | {checks.grid_streaks(r['z']):.2f} | ![](terrain/{name}.png) |")
        if name == "sketch_mcmd":
            times["acceptance"] = r["seconds"]
    md.append("")


def mdi_against_mcmd(run: Runner, md: list):
    dem = os.path.join(voids.DEM_DIR, "nasadem3_mt_washington_513.tif")
    if not os.path.exists(dem):
        md += ["## MDI against MCMD", "", f"(skipped: {os.path.basename(dem)} is not in the DEM folder)", ""]
        return
    src = voids.read_raster(dem)
    truth = src.data.astype(np.float64)
    kept = os.path.join(WORK, "washington_kept3.tif")
    removed = voids.punch_kept3(truth.shape, 0)
    voids.write_voided(dem, kept, removed, src)
    every8 = np.zeros(truth.shape, dtype=bool)
    every8[::8, ::8] = True
    coarse = os.path.join(WORK, "washington_every8.tif")
    gt = src.gt  # coarse cell i's centre is fine cell 8i's: the origin 3.5 fine cells out
    sub = src.data[::8, ::8]
    ds = gdal.GetDriverByName("GTiff").Create(coarse, sub.shape[1], sub.shape[0], 1, src.gdal_type)
    ds.SetGeoTransform((gt[0] - 3.5 * gt[1], 8 * gt[1], 0, gt[3] - 3.5 * gt[5], 0, 8 * gt[5]))
    ds.SetProjection(src.wkt)
    ds.GetRasterBand(1).WriteArray(sub)
    ds = None
    md += ["## MDI against MCMD: what the older bottom-up pass measures", "",
           "Seed 001's MDI (each ascendant the plain mean of its known children plus a displacement "
           "proportional to their mean distance, then plain MD) against the paper's MDBU + MD and the "
           "default method, reconstructing Mount Washington (NASADEM, 513×513) from a random 3.3 % of "
           "its cells (the paper's experiment) and from every 8th cell (`-upsample 8`). RMSE over the "
           "cells not given, in metres.", "",
           "| method | options | RMSE, 3.3 % kept | RMSE, every 8th cell | lattice (3.3 %) |", "|---|---|---|---|---|"]
    rows = [("MDI, te", ["-method", "mdi", "-scheme", "te"]),
            ("MCMD paper, te", ["-method", "paper-te", "-I", "1", "-Ibu", "6"]),
            ("MDI, te, noise", ["-method", "mdi", "-scheme", "te", "-rs", "0.5", "-H", "0.45"]),
            ("MCMD paper, te, noise", ["-method", "paper-te", "-I", "1", "-Ibu", "6", "-rs", "0.5", "-H", "0.45"]),
            ("MDI, ds", ["-method", "mdi", "-scheme", "ds"]),
            ("MCMD paper, ds", ["-method", "paper-ds", "-I", "1", "-Ibu", "6"]),
            ("default method", [])]
    rmse = {}
    for label, args in rows:
        tag = label.replace(",", "").replace(" ", "_").lower()
        a = run.terrain("wash_" + tag, args, kept, picture=tag in ("mdi_te_noise", "mcmd_paper_te_noise",
                                                                     "default_method"))
        b = run.terrain("wash8_" + tag, args + ["-upsample", "8"], coarse, picture=False)
        rmse[tag] = float(np.sqrt(np.mean((a["z"][removed] - truth[removed]) ** 2)))
        rmse_b = float(np.sqrt(np.mean((b["z"][~every8] - truth[~every8]) ** 2)))
        md.append(f"| {label} | `{' '.join(args) or '(defaults)'}` | {rmse[tag]:.1f} | {rmse_b:.1f} | "
                  f"{checks.grid_streaks(a['z']):.2f} |")
    md += ["", "What it measures: without noise MDI is MDBU with equal weights, and Δ's weights barely "
           "differ here (d_max is the raster's diagonal, a level's children all lie at h or h·√2), so "
           f"the two reconstruct alike ({rmse['mdi_te']:.1f} m and {rmse['mcmd_paper_te']:.1f} m). With "
           "noise they part: MDI displaces every cell it sets bottom-up, MCMD only top-down "
           f"({rmse['mdi_te_noise']:.1f} m against {rmse['mcmd_paper_te_noise']:.1f} m at `-rs 0.5 -H 0.45`). "
           "The seed's other MDI faults (children weighted by arrival order, the stored recursion "
           "tree) are implementation matters this implementation does not reproduce.", "",
           "| MDI, te, noise | MCMD paper, te, noise | default method |", "|---|---|---|",
           "| ![](terrain/wash_mdi_te_noise.png) | ![](terrain/wash_mcmd_paper_te_noise.png) | "
           "![](terrain/wash_default_method.png) |", ""]


def times_table(md: list, times: dict, repeats: int):
    s, k, l, m = times["sketch"], times["skeleton"], times["lsystem"], times["material"]
    md += ["## Whole-process times against the paper's", "",
           f"Wall time of one `mcmd_terrain` process (read the sketch, make the terrain, write a Float32 "
           f"GeoTIFF; no hillshade), the best of {repeats} runs, against the times the paper gives for its "
           "whole process on a Pentium IV 4 GHz (2007). The paper methods run on one core; the default "
           "method's solve uses both, and is the one slowed most when other jobs share the machine.", "",
           "| model | paper | ours, paper te | ours, paper ds | ours, default method |", "|---|---|---|---|---|",
           f"| a million points from a sketch (Fig. 12) | 0.25 s | {f(s['te'])} s | {f(s['ds'])} s | {f(s['mcmd'])} s |",
           f"| a quarter million from a skeleton, skeleton included (Fig. 11a) | 0.61 s (0.5 + 0.11) | "
           f"{f(k['te'])} s | {f(k['ds'])} s | {f(k['mcmd'])} s |",
           f"| a quarter million around an L-system (Fig. 11b) | 0.12 s | {f(l['te'])} s | — | — |",
           f"| a million points, material + two 5×5 median passes (Fig. 13) | 3.66 s (0.34 + 3.32) | "
           f"{f(m['te'])} s ({f(m['raw'])} s without the median) | — | — |",
           f"| the acceptance sketch, 513×513 | — | — | — | {f(times['acceptance'])} s |",
           "", f"MDI on the skeleton: {f(k['mdi'])} s; the butterfly scheme: {f(k['butterfly'])} s; the default "
           f"method on the skeleton with its erosion (the tool's default there): {f(k['eroded'])} s.", ""]


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--quick", action="store_true", help="one run per timing")
    p.add_argument("--repeats", type=int, default=5, help="runs per timing, the best kept (default 5)")
    args = p.parse_args()
    if not os.access(TOOL, os.X_OK):
        sys.exit(f"terrain_bench: {TOOL} is missing: build it first (scripts/build.sh)")
    os.makedirs(WORK, exist_ok=True)
    os.makedirs(PICS, exist_ok=True)
    repeats = 1 if args.quick else max(1, args.repeats)
    run = Runner(repeats)
    md = ["# Terrain synthesis benchmark", "",
          "The MCMD paper's terrain figures (Belhadj 2007 §4) regenerated with `mcmd_terrain`, the "
          "acceptance checks on a sketch, MDI against MCMD, and whole-process times against the "
          "paper's. Made by `bench/run_terrain.sh` (`bench/terrain_bench.py`); pictures are "
          f"hillshades from `-hillshade`, reduced to {PNG} px, in `bench/terrain/`. The paper methods run "
          "with Δ as printed (`-delta paper`): with the default normalized Δ a cell's top-down parents, "
          "all at one distance, weigh the same whatever I, and Fig. 3's shapes do not appear.", "",
          f"Machine: {voids.machine_info()}.", ""]
    times: dict = {}
    body: list = []
    acceptance(run, body, times)
    figure_2_and_3(run, body)
    figure_8(run, body)
    skeleton_figures(run, body, times)
    figure_12_and_13(run, body, times)
    mdi_against_mcmd(run, body)
    times_table(md, times, repeats)
    with open(os.path.join(HERE, "TERRAIN.md"), "w") as out:
        out.write("\n".join(md + body))
    print("terrain_bench: wrote bench/TERRAIN.md and bench/terrain/*.png")


if __name__ == "__main__":
    main()
