#!/usr/bin/python3
"""Hydrology benchmark: does a void fill keep the drainage?

On void-free DEMs from ../shared/dem with voids punched in (valleys: discs
centred on the true terrain's channels; blobs: voids.py's blob voids) x 3
seeds, plus two real-void SRTM tiles, runs every fill method and scores,
inside the voids: RMSE, strict pits, new closed-depression cells, the
agreement of the channel network with the truth's (F1, 1-cell tolerance),
and the deepest pond the fill dams upstream; with every fill's wall time.
The flow routines (Priority-Flood with and without epsilon, D8,
accumulation) are in bench/flow.py. Writes bench/HYDROLOGY.md and
bench/hydrology/*.png.

Resumable: every (case, method) result is cached as JSON under
bench/work/hydrology/results/ and is only redone when the mcmd binary (or
GDAL), the command line or the metric code (bench/flow.py) changes, or
with --force.

    /usr/bin/python3 bench/hydrology.py [--mcmd build/bin/mcmd_fillnodata]
    /usr/bin/python3 bench/hydrology.py --quick        # smoke run, ~1 min
    /usr/bin/python3 bench/hydrology.py --selfcheck    # flow routines only
"""

from __future__ import annotations

import hashlib
import inspect
import os
import shlex
import sys
import time

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import voids as V  # noqa: E402
import flow as F  # noqa: E402
from accuracy import TRUTH_DEMS as ACCURACY_DEMS  # noqa: E402

from osgeo import gdal  # noqa: E402

# void-free DEMs (or void-free crops, <= ~1.5 M cells): name -> (source, crop window)
TRUTH_DEMS = {
    "nasadem3_mt_washington_513": ("nasadem3_mt_washington_513", None),
    "nasadem3_N44W072_white_mountains": ("nasadem3_N44W072_white_mountains", None),
    "srtm3_zion": ("srtm3_zion", None),
    "ned1_half_dome_float32": ("ned1_half_dome_float32", None),
    "srtm30m_big_tujunga_utm11": ("srtm30m_big_tujunga_utm11", None),
    # the accuracy benchmark's two 1025^2 crops of the 3" mosaic, and a third
    "ferranti3_coast_range_1025": ACCURACY_DEMS["ferranti3_coast_range_1025"],
    "ferranti3_basin_range_1025": ACCURACY_DEMS["ferranti3_basin_range_1025"],
    "ferranti3_sierra_1025": ("ferranti3_sierra_nevada_4801", (2400, 3000, 1025, 1025)),
    # a void-free 1025^2 window of the half-void tile's valid southern half
    # (88 % land, 12 % sea at 0 m)
    "srtm1_N48W125_south_1025": ("srtm1_N48W125_halfvoid_3601", (1400, 2314, 1025, 1025)),
    # nodata outside the land / the survey footprint: it stays nodata in the
    # scored fills and is an outlet, like the raster border
    "nz_elev_1km_land": ("nz_elev_1km_nztm_sea_nodata", None),
    "usgs_st_helens_footprint": ("usgs_st_helens_2004_2m_utm10_footprint", None),
}
REAL_DEMS = ("srtm3_N42E001_pyrenees_voids", "srtm3_N43E007_alpes_maritimes_voids")
KINDS = ("valleys", "blobs")

# name -> (label, type, mcmd arguments; "<seed>" is the case's seed)
METHODS = {
    "mcmd": ("mcmd (default)", "mcmd", []),
    "mcmd-rs-auto": ("mcmd -rs auto", "mcmd", ["-rs", "auto", "-seed", "<seed>"]),
    "paper-ds": ("paper-ds", "mcmd", ["-method", "paper-ds"]),
    "paper-te": ("paper-te", "mcmd", ["-method", "paper-te"]),
    "mcmd-morph": ("mcmd -morph auto", "mcmd", ["-morph", "auto"]),
    "mcmd-morph-rs": ("mcmd -morph auto -rs auto", "mcmd",
                      ["-morph", "auto", "-rs", "auto", "-seed", "<seed>"]),
    "mcmd-morph-tiled": ("mcmd -morph auto, through tiles", "mcmd",
                         ["-morph", "auto", "-o", "TILING=ALWAYS"]),
    "gdal": ("gdal -si 2", "gdal", None),
    "ceiling": ("truth-channel ceiling", "ceiling", []),
    "rivers": ("true channels as -rivers", "rivers", ["-rivers", "<rivers>"]),
}
# What a row's command stands for, where it is not plain.
METHOD_NOTES = {
    "mcmd-morph-tiled": "what a raster of more than 2^21 cells gets: channels through the voids "
                        "solved alone (up to 128 cells across), none through larger ones",
}
DEFAULT = "mcmd"
REF = "gdal"
PICTURED = ("mcmd", "ceiling", "gdal", "mcmd-morph", "mcmd-morph-rs", "rivers")
TIME_LIMIT = 1.5          # -morph auto must stay <= 1.5x the default's time

# Identities of the metric code: valley and ceiling inputs are remade when
# the channel definition changes (CHANNEL_ID), results when any scoring code
# changes (METRIC_ID); both set below the code they hash.
CHANNEL_ID = METRIC_ID = None

log = V.log


def parse_args(argv=None):
    ap = V.common_parser(__doc__, "smoke run: 2 small DEMs, seed 0, 1 real-void tile; writes "
                         "bench/work/HYDROLOGY-quick.md, not bench/HYDROLOGY.md",
                         "restrict to DEMs whose name contains this (repeatable)")
    ap.add_argument("--selfcheck", action="store_true",
                    help="only test the flow routines on tiny hand-made grids, then exit")
    ap.add_argument("--methods", default=",".join(METHODS),
                    help="comma list from: " + ",".join(METHODS) + " and the --extra names")
    ap.add_argument("--extra", action="append", default=[], metavar="NAME=ARGS",
                    help="another mcmd method: NAME=mcmd arguments, '<seed>' for the case's "
                         "seed, e.g. --extra \"morph2=-morph auto -o X=1\" (repeatable; "
                         "a built-in NAME gets these arguments instead)")
    ap.add_argument("--kinds", default=",".join(KINDS), help="void kinds (valleys,blobs)")
    ap.add_argument("--seeds", type=int, default=3, help="seeds 0..N-1 (default 3)")
    ap.add_argument("--no-real", action="store_true", help="skip the real-void SRTM tiles")
    ap.add_argument("--dem-dir", default=None,
                    help="folder of the DEMs (default ../shared/dem from the project root, "
                         "or $MCMD_DEM_DIR)")
    ap.add_argument("--timeout", type=float, default=600, help="per-run timeout, s (600)")
    ap.add_argument("--repeat", type=int, default=3,
                    help="runs per fill, the methods of a case in interleaved rounds; the "
                         "median wall time is reported (3)")
    ap.add_argument("--work", default=None,
                    help="work folder (default bench/work/hydrology, or bench/work/hydrology-quick)")
    ap.add_argument("--out", default=None, help="markdown file (default bench/HYDROLOGY.md)")
    ap.add_argument("--png-dir", default=None, help="PNG folder (default bench/hydrology)")
    ap.add_argument("--no-png", action="store_true")
    a = ap.parse_args(argv)
    if a.dem_dir:
        V.DEM_DIR = os.path.abspath(a.dem_dir)
    methods = dict(METHODS)
    for e in a.extra:
        name, sep, args = e.partition("=")
        name = name.strip()
        if not sep or not name:
            ap.error(f"--extra wants NAME=ARGS, got {e!r}")
        label = methods[name][0] if name in methods and methods[name][1] == "mcmd" else \
            f"{name} ({args.strip()})"
        methods[name] = (label, "mcmd", shlex.split(args))
    a.extra_names = [e.partition("=")[0].strip() for e in a.extra]
    a.method_table = methods
    a.methods = [m.strip() for m in a.methods.split(",") if m.strip()]
    for n in a.extra_names:
        if n not in a.methods:
            a.methods.append(n)
    for m in a.methods:
        if m not in methods:
            ap.error(f"unknown method {m!r}")
    if DEFAULT not in a.methods:
        a.methods.insert(0, DEFAULT)    # time ratios and the ceiling need it
    a.kinds = [k.strip() for k in a.kinds.split(",") if k.strip()]
    for k in a.kinds:
        if k not in KINDS:
            ap.error(f"unknown void kind {k!r}")
    if a.quick:
        a.seeds = 1
        dems = ["nasadem3_mt_washington_513", "srtm3_zion"]
        reals = ["srtm3_N43E007_alpes_maritimes_voids"]
        a.out = a.out or os.path.join(V.BENCH_DIR, "work", "HYDROLOGY-quick.md")
        a.png_dir = a.png_dir or os.path.join(V.BENCH_DIR, "work", "hydrology-quick")
    else:
        dems = list(TRUTH_DEMS)
        reals = [] if a.no_real else list(REAL_DEMS)
    if a.only:
        dems = [d for d in TRUTH_DEMS if any(o in d for o in a.only)]
        reals = [] if a.no_real else [d for d in REAL_DEMS if any(o in d for o in a.only)]
    a.dems, a.reals = dems, reals
    a.out = a.out or os.path.join(V.BENCH_DIR, "HYDROLOGY.md")
    a.png_dir = a.png_dir or os.path.join(V.BENCH_DIR, "hydrology")
    a.work = a.work or os.path.join(V.BENCH_DIR, "work", "hydrology" + ("-quick" if a.quick else ""))
    a.mcmd = os.path.abspath(a.mcmd)
    return a


# --------------------------------------------------------------------------
# truth analysis, valley voids, ceiling inputs
# --------------------------------------------------------------------------

class Truth:
    """A void-free DEM with its flow analysis (computed once per DEM)."""

    def __init__(self, path: str):
        self.path = path
        self.r = V.read_raster(path)
        self.z = self.r.data
        self.valid = self.r.valid()
        self.dist = F.pixel_dist(*V.pixel_size_m(path))
        self.n_ref = int(self.valid.sum())
        self.a = F.analyse(self.z, self.valid, self.dist, n_ref=self.n_ref)
        self.raised = self.a["plain"] > self.z
        self.pits = F.strict_pits(self.z, self.valid)

    def valley_centres(self) -> np.ndarray:
        """Channel cells with a strictly lower 8-neighbour in the raw truth:
        a channel that follows the terrain, not an epsilon path across a
        flat (lakes, sea at 0 m, flat valley floors)."""
        z = self.z.astype(np.float64)
        h, w = z.shape
        lower = np.zeros(z.shape, dtype=bool)
        for dy, dx in zip(F.DY, F.DX):
            dy, dx = int(dy), int(dx)
            ys = slice(max(0, dy), h + min(0, dy))
            yd = slice(max(0, -dy), h + min(0, -dy))
            xs = slice(max(0, dx), w + min(0, dx))
            xd = slice(max(0, -dx), w + min(0, -dx))
            lower[yd, xd] |= (z[ys, xs] < z[yd, xd]) & self.valid[ys, xs]
        return self.a["channel"] & lower & self.valid


def truth_path(dem: str, work: str) -> str:
    src, crop = TRUTH_DEMS[dem]
    return V.source_path(src, crop, work, name=dem)


def make_case_input(truth: Truth, inp: str, kind: str, seed: int) -> dict:
    if kind == "valleys":
        def punch_fn(src, truth=truth, seed=seed):
            return V.punch_valleys(src.shape, seed, truth.valley_centres(), valid=truth.valid)[0]
        return V.make_voided(truth.path, inp, kind, seed, punch_fn=punch_fn, tag=CHANNEL_ID)
    return V.make_voided(truth.path, inp, kind, seed)


def make_ceiling_input(truth: Truth, removed: np.ndarray, path: str, seed: int) -> dict:
    """The case's input with its true channel cells given back (true heights)."""
    back = removed & truth.a["channel"]

    def punch_fn(src, removed=removed, back=back):
        return removed & ~back
    info = V.make_voided(truth.path, path, "ceiling", seed, punch_fn=punch_fn, tag=CHANNEL_ID)
    info["given_back"] = int(back.sum())
    return info


# --------------------------------------------------------------------------
# scoring
# --------------------------------------------------------------------------

RIVER_REACH = 4   # the river mask: truth-channel cells within this many cells of a void


def make_rivers_input(truth: Truth, removed: np.ndarray, inp: str, path: str) -> None:
    """A -rivers raster mask on the input's grid: the truth's channel cells in
    and within RIVER_REACH cells of the voids (what a user with a stream
    network would give; the lines reach known cells on both sides)."""
    near = F.dilate8(removed)
    for _ in range(RIVER_REACH - 1):
        near = F.dilate8(near)
    mask = (truth.a["channel"] & near).astype(np.uint8)
    src = gdal.Open(inp)
    ds = gdal.GetDriverByName("GTiff").Create(path, src.RasterXSize, src.RasterYSize, 1, gdal.GDT_Byte,
                                              ["COMPRESS=DEFLATE"])
    ds.SetGeoTransform(src.GetGeoTransform())
    ds.SetProjection(src.GetProjection())
    ds.GetRasterBand(1).WriteArray(mask)
    ds = None


def _max_or_none(x):
    return float(np.max(x)) if x.size else None


def score(out_path: str, inp: V.Raster, removed: np.ndarray, truth: Truth | None,
          chan_path: str | None = None) -> dict:
    """Hydrology metrics of one fill over the removed cells (see HYDROLOGY.md)."""
    f = V.read_raster(out_path)
    n = int(removed.sum())
    if truth is not None:
        r = V.metrics(truth.z, f.data, removed, f.nodata)
        valid = V.valid_mask(f.data, f.nodata) & truth.valid    # nodata of the truth stays nodata
        dist, n_ref = truth.dist, truth.n_ref
    else:
        r = V.completeness(removed, f.data, f.nodata)
        valid = V.valid_mask(f.data, f.nodata)
        dist, n_ref = F.pixel_dist(*V.pixel_size_m(out_path)), None
    r["known_exact"] = V.known_unchanged(inp.data, inp.valid(), f.data)
    z = f.data
    a = F.analyse(z, valid, dist, n_ref=n_ref)
    filled = removed & valid
    ring = F.dilate8(removed) & ~removed & valid
    pits = F.strict_pits(z, valid) & filled
    raised = (a["plain"] > z) & filled
    pond = (a["plain"] - z.astype(np.float64))[ring]
    r.update({
        "threshold": a["threshold"],
        "pits": int(pits.sum()),
        "dep_cells": int(raised.sum()),
        "dep_per100": 100.0 * int(raised.sum()) / n if n else None,
        "pond_m": _max_or_none(pond),
        "channel_cells_void": int((a["channel"] & filled).sum()),
    })
    if truth is not None:
        r["pits_truth"] = int((truth.pits & removed).sum())
        r["dep_cells_truth"] = int((truth.raised & removed).sum())
        r["new_dep_per100"] = 100.0 * (r["dep_cells"] - r["dep_cells_truth"]) / n if n else None
        tp = (truth.a["plain"] - truth.z.astype(np.float64))[ring]
        r["pond_truth_m"] = _max_or_none(tp)
        r.update(F.f1_scores(a["channel"], truth.a["channel"], removed))
    if chan_path:
        np.save(chan_path, np.packbits(a["channel"]))
    return r


def load_channel(path: str, shape) -> np.ndarray | None:
    try:
        bits = np.load(path)
    except OSError:
        return None
    return np.unpackbits(bits)[:shape[0] * shape[1]].reshape(shape).astype(bool)


def _code_id(*objs) -> str:
    h = hashlib.sha256(open(os.path.join(V.BENCH_DIR, "flow.py"), "rb").read())
    for o in objs:
        h.update(inspect.getsource(o).encode())
    return h.hexdigest()[:12]


CHANNEL_ID = "chan-" + _code_id(Truth)
METRIC_ID = "metric-" + _code_id(Truth, score, V.metrics, V.completeness)


# --------------------------------------------------------------------------
# main
# --------------------------------------------------------------------------

def method_cmd(a, m: str, src: str, dst: str, md: int, seed: int, rivers: str = "") -> list[str]:
    label, typ, args = a.method_table[m]
    if typ == "gdal":
        return V.fill_cmd("gdal-si2", src, dst, md, a.mcmd)
    args = [x.replace("<seed>", str(seed)).replace("<rivers>", rivers) for x in args]
    return [a.mcmd, "-q"] + args + [src, dst]


def main(argv=None):
    a = parse_args(argv)
    if a.selfcheck:
        return 0 if F.selfcheck() else 1
    if not F.selfcheck():
        log("the flow routines fail their self-check: no benchmark with a broken metric")
        return 1
    t_start = time.time()
    work = a.work
    V.make_work_dirs(work)

    # which methods can run: the CLI, then each mcmd option set once
    ok, msg = V.mcmd_status(a.mcmd)
    methods, notes = [], {}
    for m in a.methods:
        typ, args = a.method_table[m][1], a.method_table[m][2]
        if typ == "gdal":
            methods.append(m)
        elif not ok:
            notes[m] = msg.splitlines()[0]
        else:
            probe = [x.replace("<seed>", "0") for x in args if x not in ("-rivers", "<rivers>")]
            acc, why = V.mcmd_accepts(a.mcmd, probe)
            if acc:
                methods.append(m)
            else:
                notes[m] = f"the CLI rejects `{' '.join(args)}` ({why})"
    for m, why in notes.items():
        log(f"WARNING: {m} not run: {why}")
    if REF not in methods:
        log("WARNING: gdal_fillnodata.py is not among the methods")
    key = V.run_key(a.mcmd) + " " + METRIC_ID
    version = ""
    if ok:
        import subprocess
        try:
            version = subprocess.run([a.mcmd, "--version"], capture_output=True, text=True,
                                     timeout=30).stdout.strip().splitlines()[0]
        except Exception:  # noqa: BLE001
            version = "?"

    cases = []    # dicts
    for dem in a.dems:
        for kind in a.kinds:
            for seed in range(a.seeds):
                cases.append({"id": f"{dem}__{kind}__s{seed}", "dem": dem, "kind": kind,
                              "seed": seed})
    for dem in a.reals:
        cases.append({"id": f"{dem}__real", "dem": dem, "kind": "real", "seed": 0})
    log(f"hydrology: {len(cases)} cases x {len(methods)} methods ({', '.join(methods)}); "
        f"work in {work}")

    results = {}
    truth, truth_dem = None, None
    t_metric = 0.0
    for i, c in enumerate(cases):
        log(f"[{i + 1}/{len(cases)}] {c['id']}")
        if c["kind"] == "real":
            inp = os.path.join(V.DEM_DIR, c["dem"] + ".tif")
            tr = None
        else:
            if truth_dem != c["dem"]:
                truth, truth_dem = Truth(truth_path(c["dem"], work)), c["dem"]
            tr = truth
            inp = os.path.join(work, "inputs", c["id"] + ".tif")
            make_case_input(tr, inp, c["kind"], c["seed"])
        c["input"] = inp
        inr = V.read_raster(inp)
        removed = ~inr.valid()
        if tr is not None:
            removed &= tr.valid
        c["void_cells"] = int(removed.sum())
        w, h = V.raster_size(inp)
        specs = []
        for m in methods:
            src, src_r, rivers = inp, inr, ""
            if a.method_table[m][1] == "rivers":
                if tr is None:
                    continue       # no truth, no true channels
                rivers = os.path.join(work, "inputs", c["id"] + "__rivers.tif")
                make_rivers_input(tr, removed, inp, rivers)
            if a.method_table[m][1] == "ceiling":
                if tr is None:
                    continue       # no truth, no ceiling
                src = os.path.join(work, "inputs", c["id"] + "__ceiling.tif")
                ci = make_ceiling_input(tr, removed, src, c["seed"])
                c["given_back"] = ci["given_back"]
                src_r = V.read_raster(src)
            out = os.path.join(work, "out", f"{c['id']}__{m}.tif")
            chan = out + ".chan.npy" if (c["kind"] == "valleys" and c["seed"] == 0) else None

            def evaluate(out_path, src_r=src_r, removed=removed, tr=tr, chan=chan):
                nonlocal t_metric
                t0 = time.time()
                r = score(out_path, src_r, removed, tr, chan)
                t_metric += time.time() - t0
                return r
            specs.append((m, V.FillSpec(os.path.join(work, "results", f"{c['id']}__{m}.json"),
                                        method_cmd(a, m, src, out, max(w, h), c["seed"], rivers),
                                        out, a.timeout, evaluate)))
        rs = V.cached_fills([s for _, s in specs], key, force=a.force, log=log, repeat=a.repeat,
                            mem_limit_mb=a.mem_limit_mb or None)
        for (m, _), r in zip(specs, rs):
            results[(c["id"], m)] = r
    log(f"scoring took {t_metric:.0f} s")

    pngs = {} if a.no_png else make_pngs(a, cases, methods, work)
    write_report(a, cases, methods, notes, results, pngs, version, time.time() - t_start)
    log(f"wrote {a.out}")
    return 0


# --------------------------------------------------------------------------
# pictures
# --------------------------------------------------------------------------

def _write_rgb_png(rgb: np.ndarray, path: str):
    h, w, _ = rgb.shape
    mem = gdal.GetDriverByName("MEM").Create("", w, h, 3, gdal.GDT_Byte)
    for i in range(3):
        mem.GetRasterBand(i + 1).WriteArray(rgb[:, :, i])
    gdal.GetDriverByName("PNG").CreateCopy(path, mem, options=["ZLEVEL=9"])
    mem = None
    aux = path + ".aux.xml"
    if os.path.exists(aux):
        os.unlink(aux)


TRUTH_RGB = (30, 110, 255)     # truth channel only: blue
FILL_RGB = (235, 40, 20)       # fill channel only: red
BOTH_RGB = (150, 30, 170)      # both: purple
VOID_RGB = (255, 215, 0)       # void outline: yellow


def channel_overlay(shade_png: str, window, void: np.ndarray, chan_truth: np.ndarray,
                    chan_fill: np.ndarray, out_png: str):
    """The fill's hillshade (lightened), truth channels, the fill's channels
    and the void outline, at the hillshade PNG's scale."""
    xo, yo, w, h = window
    shade = gdal.Open(shade_png).ReadAsArray().astype(np.float64)
    if shade.ndim == 3:
        shade = shade[0]
    k = max(1, shade.shape[1] // w)

    def up(m):
        return np.kron(m[yo:yo + h, xo:xo + w].astype(np.uint8),
                       np.ones((k, k), np.uint8)).astype(bool)[:shade.shape[0], :shade.shape[1]]
    g = (90 + 0.6 * shade).clip(0, 255).astype(np.uint8)
    rgb = np.dstack([g, g, g])
    t, f = up(chan_truth), up(chan_fill)
    rgb[t & ~f] = TRUTH_RGB
    rgb[f & ~t] = FILL_RGB
    rgb[t & f] = BOTH_RGB
    v = up(void)
    inner = v.copy()
    inner[1:, :] &= v[:-1, :]
    inner[:-1, :] &= v[1:, :]
    inner[:, 1:] &= v[:, :-1]
    inner[:, :-1] &= v[:, 1:]
    rgb[v & ~inner] = VOID_RGB
    _write_rgb_png(rgb, out_png)


def make_pngs(a, cases, methods, work):
    """For each DEM, the largest valley void of seed 0: hillshades of the
    truth and of the pictured fills, and channel overlays of those fills."""
    out = {}
    os.makedirs(a.png_dir, exist_ok=True)
    shown = [m for m in PICTURED if m in methods]
    for c in cases:
        if c["kind"] != "valleys" or c["seed"] != 0:
            continue
        inr = V.read_raster(c["input"])
        tp = truth_path(c["dem"], work)
        tr = Truth(tp)
        void = ~inr.valid() & tr.valid
        bbox = V.largest_void_bbox(void)
        if bbox is None:
            continue
        main, _ = V.void_window(bbox, inr.shape)
        shades, overlays = [("truth", V.hillshade_png(
            tp, main, os.path.join(a.png_dir, f"{c['dem']}__truth.png")))], []
        for m in shown:
            p = os.path.join(work, "out", f"{c['id']}__{m}.tif")
            if not os.path.exists(p):
                continue
            png = os.path.join(a.png_dir, f"{c['dem']}__{m}.png")
            try:
                V.hillshade_png(p, main, png)
            except Exception as e:  # noqa: BLE001
                log(f"  hillshade failed for {p}: {e}")
                continue
            shades.append((m, png))
            chan = load_channel(p + ".chan.npy", inr.shape)
            if chan is None:     # not saved (older cache): recompute
                f = V.read_raster(p)
                chan = F.analyse(f.data, V.valid_mask(f.data, f.nodata) & tr.valid, tr.dist,
                                 n_ref=tr.n_ref)["channel"]
            ov = os.path.join(a.png_dir, f"{c['dem']}__{m}__channels.png")
            channel_overlay(png, main, void, tr.a["channel"], chan, ov)
            overlays.append((m, ov))
        out[c["id"]] = {"window": main, "bbox": bbox, "shades": shades, "overlays": overlays}
    return out


# --------------------------------------------------------------------------
# report
# --------------------------------------------------------------------------

def _ok(r):
    return bool(r and r.get("ok"))


def _vals(rs, key):
    return [r.get(key) for r in rs if _ok(r) and r.get(key) is not None]


def _ratio(r, ref, key="wall_s"):
    if not _ok(r) or not _ok(ref) or not ref.get(key):
        return None
    return r[key] / ref[key]


def write_report(a, cases, methods, notes, results, pngs, version, elapsed):
    L = []
    md_dir = os.path.dirname(os.path.abspath(a.out))
    rel = lambda p: os.path.relpath(p, md_dir)  # noqa: E731
    T = a.method_table
    mlist = methods + [m for m in a.methods if m not in methods]
    lab = lambda m: T[m][0]  # noqa: E731
    ndem = len(a.dems)
    L.append("# Hydrology: do void fills keep the drainage?" + (" (QUICK smoke run)" if a.quick else ""))
    L.append("")
    L.append("A fill that looks right can still break the drainage: a channel that stops at the "
             "void edge, a dam across a valley, a pit in the middle of a slope. This benchmark "
             "routes water over the true terrain and over every fill, independently, and "
             "compares the two inside the voids.")
    L.append("")
    L.append(f"Regenerate: `bench/run_hydrology.sh` (`--quick` smoke run, `--mcmd PATH`, "
             "`--methods m1,m2`, `--extra NAME=ARGS`, `--only DEM`, `--force`, `--selfcheck`; "
             "see bench/README.md). Every number below comes from one run of that command: "
             f"CLI `{version or 'not run'}` and `gdal_fillnodata.py` (GDAL {gdal.__version__}) "
             f"on {V.machine_info()}; {len(cases)} cases; the run took {elapsed / 60:.1f} min "
             "(cached fills reused where the binary, command and metric were unchanged).")
    L.append("")

    # ------------------------------------------------------------------ metric
    L.append("## The metric")
    L.append("")
    L.append("On the truth DEM and on each filled DEM, independently (bench/flow.py, numba):")
    L.append("")
    L.append("1. **Priority-Flood + ε** (Barnes, Lehman & Mulla 2014, the ε variant): cells are "
             "settled from the outlets upwards in order of level; the outlets (seeds) are the "
             "valid cells on the raster border or next to a nodata cell (nodata cells that remain "
             "— the sea of New Zealand, the outside of the St Helens survey — are outlets too). "
             "A cell reached from a cell of level L gets its own elevation if that is above L, "
             "else the next float64 above L (`nextafter`): depressions and flats become surfaces "
             "that fall towards their outlet by one float64 step per cell.")
    L.append("2. **D8** on that surface: each cell drains to the valid 8-neighbour of steepest "
             "descent (drop ÷ distance, distances from the pixel size in metres; geographic "
             "pixels converted at the raster's centre latitude). A cell without a lower "
             "neighbour is an outlet. **Accumulation** = the cells draining through a cell, "
             "itself included.")
    L.append(f"3. **Channel** = accumulation ≥ {100 * F.CHANNEL_FRACTION:.1f} % of the truth's "
             "valid cells (= the raster's cell count for a void-free DEM; the land cells of "
             "New Zealand, the survey footprint of St Helens). The fill is routed with the same "
             "threshold, and with the truth's nodata cells as nodata (what a fill puts in the "
             "sea is not scored).")
    L.append("4. **Plain Priority-Flood** (no ε: a reached cell gets max(its elevation, L)) "
             "gives the depression-filled level; a cell it raises by > 0 is in a closed "
             "depression.")
    L.append("")
    L.append("Scores, over the **void cells** (the removed cells; nodata of the truth excluded):")
    L.append("")
    L.append("- **RMSE** (m) of the fill against the truth.")
    L.append("- **strict pits**: void cells strictly lower than all 8 neighbours in the raw fill "
             "(only cells whose 8 neighbours are all in the raster and valid); the truth's count "
             "in the same cells is given beside it (the terrain has pits of its own, mostly "
             "integer-rounding noise).")
    L.append("- **new depression cells /100**: (void cells that plain Priority-Flood raises on "
             "the fill − void cells it raises on the truth) ÷ void cells × 100. Signed: "
             "negative = the fill has fewer closed-depression cells in the voids than the "
             "terrain had (it drains lakes and pits away), positive = it creates closed "
             "depressions (dams, pits).")
    L.append("- **flow F1**: precision P = fill-channel void cells within 1 cell "
             "(8-neighbourhood) of a truth-channel cell (anywhere) ÷ fill-channel void cells; "
             "recall R = truth-channel void cells within 1 cell of a fill-channel cell ÷ "
             "truth-channel void cells; F1 = 2PR/(P+R). A case without truth-channel void "
             "cells has no F1 and is left out of the F1 medians (\"F1 cases\" counts the rest); "
             "a fill without channel void cells where the truth has some scores F1 = 0.")
    L.append("- **deepest pond** (m): the largest (plain Priority-Flood level − fill) over the "
             "known cells 8-adjacent to a void: how deep the fill dams the terrain upstream of "
             "it. The truth's value in the same cells is beside it (a real lake or pit next to "
             "the void): a fill that does no harm matches it.")
    L.append("- **time**: whole-process wall time of the fill (median of `--repeat` runs; the "
             "methods of a case run in interleaved rounds so that they are timed in the same "
             "minutes), and its ratio to the default's on the same case.")
    L.append("")
    L.append("Medians are over the cases of a void kind (DEMs × seeds); a method's cases that "
             "failed are counted in \"ok\" and left out of the medians.")
    L.append("")

    # ------------------------------------------------------------------ cases
    L.append("## Cases")
    L.append("")
    L.append(f"{ndem} void-free DEMs or void-free crops of `../shared/dem`: "
             + ", ".join(f"`{d}`" + (f" (`{TRUTH_DEMS[d][0]}` x{TRUTH_DEMS[d][1][0]} "
                                      f"y{TRUTH_DEMS[d][1][1]} {TRUTH_DEMS[d][1][2]}×"
                                      f"{TRUTH_DEMS[d][1][3]})" if TRUTH_DEMS[d][1] else
                                      (f" (`{TRUTH_DEMS[d][0]}`)" if TRUTH_DEMS[d][0] != d else ""))
                     for d in a.dems) + ".")
    L.append("")
    L.append(f"Void kinds, seeds 0..{a.seeds - 1}:")
    L.append("")
    L.append("- **valleys**: 6–10 discs of radius 8–25 cells (uniform integers, placed largest "
             "first), each centred on a random truth-channel cell that has a strictly lower "
             "8-neighbour in the raw truth (a channel that follows the terrain, not an ε path "
             "across a lake or the sea), 8 cells clear of the raster border, with the disc and "
             "a 2-cell ring around it on valid cells and 2 cells clear of the other discs "
             "(`voids.punch_valleys`). Every disc cuts a channel: the hard case for drainage. "
             "The number and radii of the discs depend on the seed only, so every DEM gets "
             "the same void area for a seed (when all its discs find a place).")
    L.append("- **blobs**: voids.py's smooth random blobs, ~5 % of the area (one large one, "
             "some touching the border): the accuracy benchmark's voids.")
    L.append("")
    L.append("Real-void tiles (no truth): " + ", ".join(f"`{d}`" for d in a.reals) +
             " — strict pits, depression cells and the deepest pond in the filled voids only.")
    L.append("")

    # ------------------------------------------------------------------ methods
    L.append("## Methods")
    L.append("")
    L.append("| row | command |")
    L.append("|---|---|")
    for m in mlist:
        label, typ, args = T[m]
        if typ == "gdal":
            cmd = "`gdal_fillnodata.py -md <max(W,H)> -si 2 SRC DST` (the reference)"
        elif typ == "ceiling":
            cmd = ("`mcmd_fillnodata SRC' DST`, SRC' = SRC with the truth-channel void cells "
                   "given back with their true heights (the ceiling of the metric: a fill that "
                   "knew where the channels are; its time is that of a different input)")
        elif typ == "rivers":
            cmd = ("`mcmd_fillnodata -rivers MASK SRC DST`, MASK = a raster mask of the truth's "
                   f"channel cells in and within {RIVER_REACH} cells of the voids (a fill given the "
                   "stream network as lines: how well `-rivers` is followed)")
        else:
            cmd = "`mcmd_fillnodata " + " ".join(args + ["SRC", "DST"]) + "`"
            if m in METHOD_NOTES:
                cmd += f" ({METHOD_NOTES[m]})"
        note = f" — **not run**: {notes[m]}" if m in notes else ""
        L.append(f"| {label} | {cmd}{note} |")
    L.append("")

    truth_cases = [c for c in cases if c["kind"] != "real"]
    # ------------------------------------------------------------------ medians
    for kind in a.kinds:
        kc = [c for c in truth_cases if c["kind"] == kind]
        if not kc:
            continue
        L.append(f"## Medians — {kind} ({len(kc)} cases)")
        L.append("")
        L.append("| method | ok | RMSE m | strict pits (truth) | new depression cells /100 "
                 "| F1 | P / R | F1 cases | deepest pond m (truth) | time s | time / default "
                 "(worst) |")
        L.append("|---|---|---|---|---|---|---|---|---|---|---|")
        for m in mlist:
            rs = [results.get((c["id"], m)) for c in kc]
            if m in notes:
                L.append(f"| {lab(m)} | not run | " + " | ".join([""] * 9) + " |")
                continue
            okn = sum(1 for r in rs if _ok(r))
            tr = [_ratio(r, results.get((c["id"], DEFAULT))) for r, c in zip(rs, kc)]
            tr = [x for x in tr if x is not None]
            f1n = len(_vals(rs, "f1"))
            L.append("| " + " | ".join([
                lab(m), f"{okn}/{len(kc)}",
                V.fmt(V.median(_vals(rs, "rmse")), ".2f"),
                f"{V.fmt(V.median(_vals(rs, 'pits')), '.1f')} "
                f"({V.fmt(V.median(_vals(rs, 'pits_truth')), '.1f')})",
                V.fmt(V.median(_vals(rs, "new_dep_per100")), "+.2f"),
                V.fmt(V.median(_vals(rs, "f1")), ".3f"),
                f"{V.fmt(V.median(_vals(rs, 'precision')), '.2f')} / "
                f"{V.fmt(V.median(_vals(rs, 'recall')), '.2f')}",
                str(f1n),
                f"{V.fmt(V.median(_vals(rs, 'pond_m')), '.1f')} "
                f"({V.fmt(V.median(_vals(rs, 'pond_truth_m')), '.1f')})",
                V.fmt(V.median(_vals(rs, "wall_s")), ".2f"),
                f"{V.fmt(V.median(tr), '.2f')} ({V.fmt(max(tr) if tr else None, '.2f')})",
            ]) + " |")
        L.append("")

    # ------------------------------------------------------------------ checks
    L.append("## Time of `-morph auto` against the default (limit ≤ 1.5×)")
    L.append("")
    rows = []
    for m in ("mcmd-morph", "mcmd-morph-rs"):
        if m not in mlist:
            continue
        if m in notes:
            rows.append(f"| {lab(m)} | not run ({notes[m]}) | | |")
            continue
        tr = [(c["id"], _ratio(results.get((c["id"], m)), results.get((c["id"], DEFAULT))))
              for c in truth_cases]
        tr = [(cid, x) for cid, x in tr if x is not None]
        if not tr:
            rows.append(f"| {lab(m)} | no successful run | | |")
            continue
        med = V.median([x for _, x in tr])
        wc, wx = max(tr, key=lambda t: t[1])
        rows.append(f"| {lab(m)} | {med:.2f} | {wx:.2f} ({wc}) | "
                    f"{'yes' if med <= TIME_LIMIT else 'NO'} (median), "
                    f"{'yes' if wx <= TIME_LIMIT else 'NO'} (worst) |")
    if rows:
        L.append("| method | median time / default | worst case | ≤ 1.5× |")
        L.append("|---|---|---|---|")
        L.extend(rows)
    else:
        L.append("No `-morph` row among the methods.")
    L.append("")

    # ------------------------------------------------------------------ per DEM
    scored = [m for m in mlist if m not in notes]
    for kind in a.kinds:
        kc = [c for c in truth_cases if c["kind"] == kind]
        if not kc:
            continue
        L.append(f"## Per DEM — {kind} (medians over the seeds: F1 · new depression cells /100 "
                 "· deepest pond m)")
        L.append("")
        L.append("| DEM | void cells | truth pond m | " + " | ".join(lab(m) for m in scored) + " |")
        L.append("|---|---|---|" + "---|" * len(scored))
        per = {}   # (dem, m) -> (f1, dep, pond)
        for dem in a.dems:
            dc = [c for c in kc if c["dem"] == dem]
            if not dc:
                continue
            cells = []
            for m in scored:
                rs = [results.get((c["id"], m)) for c in dc]
                f1 = V.median(_vals(rs, "f1"))
                dep = V.median(_vals(rs, "new_dep_per100"))
                pond = V.median(_vals(rs, "pond_m"))
                per[(dem, m)] = (f1, dep, pond)
                cells.append(f"{V.fmt(f1, '.2f')} · {V.fmt(dep, '+.1f')} · {V.fmt(pond, '.0f')}")
            ref = [results.get((c["id"], DEFAULT)) for c in dc]
            L.append(f"| {dem} | {V.fmt(V.median([c['void_cells'] for c in dc]), '.0f')} | "
                     f"{V.fmt(V.median(_vals(ref, 'pond_truth_m')), '.0f')} | " +
                     " | ".join(cells) + " |")
        L.append("")
        L.append(f"Worst DEM per method ({kind}): lowest median F1, highest median new "
                 "depression cells /100, deepest median pond.")
        L.append("")
        L.append("| method | lowest F1 | most new depression cells | deepest pond |")
        L.append("|---|---|---|---|")
        for m in scored:
            def worst(i, hi):
                xs = [(d, per[(d, m)][i]) for d in a.dems if (d, m) in per and per[(d, m)][i] is not None]
                if not xs:
                    return "—"
                d, x = (max if hi else min)(xs, key=lambda t: t[1])
                return f"{d} ({x:{'+.1f' if i == 1 else ('.0f' if i == 2 else '.2f')}})"
            L.append(f"| {lab(m)} | {worst(0, False)} | {worst(1, True)} | {worst(2, True)} |")
        L.append("")

    # ------------------------------------------------------------------ real
    real = [c for c in cases if c["kind"] == "real"]
    if real:
        L.append("## Real-void tiles (no truth: in the filled voids)")
        L.append("")
        L.append("Strict pits · depression cells /100 void cells (plain Priority-Flood raises "
                 "them; not a difference: the terrain under the voids is unknown) · deepest "
                 "pond m (it includes the tile's own depressions next to its voids, so only "
                 "the differences between methods mean something) · time s.")
        L.append("")
        rm = [m for m in scored if T[m][1] not in ("ceiling", "rivers")]
        L.append("| tile | void cells | " + " | ".join(lab(m) for m in rm) + " |")
        L.append("|---|---|" + "---|" * len(rm))
        for c in real:
            cells = [V.result_cell(results.get((c["id"], m)), lambda r: (
                f"{r['pits']} · {V.fmt(r.get('dep_per100'), '.2f')} · "
                f"{V.fmt(r.get('pond_m'), '.0f')} · {r['wall_s']:.2f}")) for m in rm]
            L.append(f"| {c['dem']} | {c['void_cells']} | " + " | ".join(cells) + " |")
        L.append("")

    # ------------------------------------------------------------------ pictures
    if pngs:
        L.append("## Pictures: the largest valley void of each DEM (seed 0)")
        L.append("")
        L.append("Top: `gdaldem hillshade -z 2` of a window around the void (enlarged by an "
                 "integer factor to ≤ 256 px). Bottom: channels over the fill's hillshade — "
                 "blue = truth channel only, red = the fill's channel only, purple = both, "
                 "yellow = void outline. A fill that keeps the drainage shows purple through the "
                 "void; a red line beside a blue one is a channel that moved; blue alone in the "
                 "void is a channel the fill lost (a dam or a flat).")
        L.append("")
        for cid, info in pngs.items():
            x, y, w, h = info["window"]
            L.append(f"**{cid.split('__')[0]}** — window x={x} y={y} {w}×{h}")
            L.append("")
            sh = info["shades"]
            L.append("| " + " | ".join(("truth" if m == "truth" else lab(m)) for m, _ in sh) + " |")
            L.append("|" + "---|" * len(sh))
            L.append("| " + " | ".join(f"![{m}]({rel(p)})" for m, p in sh) + " |")
            ov = dict(info["overlays"])
            L.append("| " + " | ".join(
                ("channels:" if m == "truth" else
                 (f"![{m} channels]({rel(ov[m])})" if m in ov else "")) for m, _ in sh) + " |")
            L.append("")

    # ------------------------------------------------------------------ all runs
    L.append("## All runs")
    L.append("")
    L.append("| case | method | RMSE | pits (truth) | new dep /100 | F1 | P | R | pond m (truth) "
             "| time s | status |")
    L.append("|---|---|---|---|---|---|---|---|---|---|---|")
    for c in cases:
        for m in mlist:
            if m in notes:
                continue
            r = results.get((c["id"], m))
            if not r:
                continue
            st = "ok" if r.get("ok") else r.get("error", "failed").replace("|", "/")[:80]
            if r.get("ok") and r.get("known_exact") is False:
                st = "ok, but KNOWN CELLS CHANGED"
            if r.get("ok") and r.get("completeness", 1) < 1:
                st += f", {100 * r['completeness']:.2f} % filled"
            pt = f" ({r['pits_truth']})" if r.get("pits_truth") is not None else ""
            pdt = f" ({V.fmt(r.get('pond_truth_m'), '.1f')})" if r.get("pond_truth_m") is not None else ""
            dep = r.get("new_dep_per100", r.get("dep_per100"))
            L.append("| " + " | ".join([
                c["id"], lab(m), V.fmt(r.get("rmse"), ".2f"),
                (str(r["pits"]) if r.get("pits") is not None else "—") + pt,
                V.fmt(dep, "+.2f" if "new_dep_per100" in r else ".2f"),
                V.fmt(r.get("f1"), ".3f"), V.fmt(r.get("precision"), ".2f"),
                V.fmt(r.get("recall"), ".2f"), V.fmt(r.get("pond_m"), ".1f") + pdt,
                V.fmt(r.get("wall_s"), ".2f"), st]) + " |")
    L.append("")
    os.makedirs(md_dir, exist_ok=True)
    with open(a.out, "w") as f:
        f.write("\n".join(L))


if __name__ == "__main__":
    sys.exit(main())
