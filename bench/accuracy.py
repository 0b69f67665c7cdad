#!/usr/bin/python3
"""Accuracy benchmark: mcmd methods vs gdal_fillnodata, GRASS r.fillnulls and
SAGA's Close Gaps tools.

On void-free DEMs from ../shared/dem with voids punched in (kept3: a random
3.3 % of cells kept; blobs: ~5 % of the area in blob voids; big: one void a
quarter of the width across) x 3 seeds, the void masks of the two real-void
SRTM tiles laid onto void-free DEMs of similar terrain (realvoids), plus the
real-void tiles themselves, runs every mcmd method,
``gdal_fillnodata.py -md <max(W,H)> -si 0`` and ``-si 2`` and the peers of
bench/peers.py in the same run, and records RMSE, max error,
Laplacian-spread and mean-slope ratios inside the voids, whole-process time
and peak RSS, and hillshade PNGs of the largest void.
Writes bench/ACCURACY.md and bench/accuracy/*.png.

Resumable: every (case, method) result is cached as JSON under
bench/work/accuracy/results/ and is only redone when the mcmd binary (or
GDAL) or the command line changes, or with --force.

    /usr/bin/python3 bench/accuracy.py [--mcmd build/bin/mcmd_fillnodata]
    /usr/bin/python3 bench/accuracy.py --quick          # smoke run, ~1 min
"""

from __future__ import annotations

import os
import sys
import time

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import accuracy_report as R  # noqa: E402
import peers as P  # noqa: E402
import voids as V  # noqa: E402

# void-free DEMs: name -> (source file, crop window or None)
TRUTH_DEMS = {
    "nasadem3_mt_washington_513": ("nasadem3_mt_washington_513", None),
    "nasadem3_N44W072_white_mountains": ("nasadem3_N44W072_white_mountains", None),
    "srtm3_zion": ("srtm3_zion", None),
    "ned1_half_dome_float32": ("ned1_half_dome_float32", None),
    "srtm30m_big_tujunga_utm11": ("srtm30m_big_tujunga_utm11", None),
    # extra terrains cut out of the void-free 3" mosaic (cheap, 1025^2)
    "ferranti3_coast_range_1025": ("ferranti3_california_nevada_10801x4801", (0, 0, 1025, 1025)),
    "ferranti3_basin_range_1025": ("ferranti3_california_nevada_10801x4801", (7500, 1500, 1025, 1025)),
}
EXTRA_DEMS = ("ferranti3_coast_range_1025", "ferranti3_basin_range_1025")
REAL_DEMS = ("srtm3_N42E001_pyrenees_voids", "srtm3_N43E007_alpes_maritimes_voids")
# realvoids: the void masks of the real-void tiles (1201², 3") laid onto
# void-free 1201² DEMs of mountain terrain, as is (seed 0), mirrored left-right
# (1) or turned half a turn (2).
REAL_MASKS = {"pyrenees": "srtm3_N42E001_pyrenees_voids",
              "alpes_maritimes": "srtm3_N43E007_alpes_maritimes_voids"}
MASK_HOSTS = {
    "nasadem3_N44W072_white_mountains": ("nasadem3_N44W072_white_mountains", None),
    "ferranti3_sierra_1201": ("ferranti3_california_nevada_10801x4801", (3800, 2500, 1201, 1201)),
}
KINDS = list(V.VOID_KINDS) + ["realvoids"]

MCMD_ROWS = ["mcmd", "mcmd-rs-auto", "paper-ds", "paper-te"]
GDAL_ROWS = ["gdal-si0", "gdal-si2"]
ALL_METHODS = MCMD_ROWS + GDAL_ROWS + [p for p in P.PEERS if p != "grass-rst-stock"]
REF = R.REF


log = V.log


def parse_args(argv=None):
    ap = V.common_parser(__doc__, "smoke run: 1 DEM (513^2), 1 seed, 1 real-void tile; "
                         "writes bench/work/ACCURACY-quick.md, not bench/ACCURACY.md", "restrict to DEMs whose name contains this (repeatable)")
    ap.add_argument("--methods", default=",".join(ALL_METHODS),
                    help="comma list from: " + ",".join(ALL_METHODS) + " (and grass-rst-stock: "
                         "r.fillnulls itself, slow, fails on geographic rasters)")
    ap.add_argument("--kinds", default=",".join(KINDS), help="void kinds (" + ",".join(KINDS) + ")")
    ap.add_argument("--seeds", type=int, default=3, help="seeds 0..N-1 (default 3)")
    ap.add_argument("--no-extra", action="store_true",
                    help="skip the two extra 1025^2 crops of the 3\" mosaic")
    ap.add_argument("--no-real", action="store_true", help="skip the real-void SRTM tiles")
    ap.add_argument("--timeout", type=float, default=600, help="per-run timeout, s (600)")
    ap.add_argument("--timeout-peers", type=float, default=1800,
                    help="per-run timeout of a GRASS or SAGA fill, s (1800)")
    ap.add_argument("--peer-seeds", type=int, default=None,
                    help="run GRASS and SAGA on seeds 0..N-1 only (default: every seed); "
                         "their fills take seconds to a quarter of an hour each")
    ap.add_argument("--cached-peers", action="store_true",
                    help="run no GRASS or SAGA fill: report those already cached (a reduced "
                         "set, when the machine's time did not allow every case)")
    ap.add_argument("--repeat-peers", type=int, default=1,
                    help="runs per GRASS or SAGA fill (1: they take seconds to minutes, "
                         "far beyond the timing noise)")
    ap.add_argument("--repeat", type=int, default=5,
                    help="runs per fill, the methods of a case in interleaved rounds; the median wall time is reported (5)")
    ap.add_argument("--work", default=None,
                    help="work folder (default bench/work/accuracy, or bench/work/accuracy-quick)")
    ap.add_argument("--out", default=None, help="markdown file (default bench/ACCURACY.md)")
    ap.add_argument("--png-dir", default=None, help="PNG folder (default bench/accuracy)")
    ap.add_argument("--no-png", action="store_true")
    a = ap.parse_args(argv)
    a.methods = [m.strip() for m in a.methods.split(",") if m.strip()]
    for m in a.methods:
        if m not in ALL_METHODS + ["grass-rst-stock"]:
            ap.error(f"unknown method {m!r}")
    if REF not in a.methods:
        a.methods.append(REF)     # ratios need the reference
    a.kinds = [k.strip() for k in a.kinds.split(",") if k.strip()]
    for k in a.kinds:
        if k not in KINDS:
            ap.error(f"unknown void kind {k!r}")
    a.hosts = list(MASK_HOSTS)
    if a.quick:
        a.seeds = 1
        dems = ["nasadem3_mt_washington_513"]
        reals = ["srtm3_N43E007_alpes_maritimes_voids"]
        a.hosts = []
        a.out = a.out or os.path.join(V.BENCH_DIR, "work", "ACCURACY-quick.md")
        a.png_dir = a.png_dir or os.path.join(V.BENCH_DIR, "work", "accuracy-quick")
    else:
        dems = [d for d in TRUTH_DEMS if not (a.no_extra and d in EXTRA_DEMS)]
        reals = [] if a.no_real else list(REAL_DEMS)
    if a.only:
        dems = [d for d in TRUTH_DEMS if any(o in d for o in a.only)]
        reals = [] if a.no_real else [d for d in REAL_DEMS if any(o in d for o in a.only)]
        a.hosts = [d for d in MASK_HOSTS if any(o in d for o in a.only)]
    a.dems, a.reals = dems, reals
    a.out = a.out or os.path.join(V.BENCH_DIR, "ACCURACY.md")
    a.png_dir = a.png_dir or os.path.join(V.BENCH_DIR, "accuracy")
    a.work = a.work or os.path.join(V.BENCH_DIR, "work", "accuracy" + ("-quick" if a.quick else ""))
    a.mcmd = os.path.abspath(a.mcmd)
    return a


def truth_path(dem: str, work: str) -> str:
    src, crop = TRUTH_DEMS[dem] if dem in TRUTH_DEMS else MASK_HOSTS[dem]
    return V.source_path(src, crop, work, name=dem)


def real_mask(mask: str, seed: int, shape) -> np.ndarray:
    """The void mask of real-void tile MASK, oriented by SEED (as is, mirrored
    left-right, turned half a turn)."""
    void = ~V.read_raster(os.path.join(V.DEM_DIR, REAL_MASKS[mask] + ".tif")).valid()
    void = [void, void[:, ::-1], void[::-1, ::-1]][seed % 3]
    if void.shape != tuple(shape):
        raise ValueError(f"mask {mask} is {void.shape}, the host {tuple(shape)}")
    return np.ascontiguousarray(void)


def truth_cases(a, work):
    """(case_id, dem, kind, seed, input, truth) of every case with a truth."""
    cases = []
    for kind in a.kinds:
        if kind == "realvoids":
            continue
        for dem in a.dems:
            tp = truth_path(dem, work)
            for seed in range(a.seeds):
                cid = f"{dem}__{kind}__s{seed}"
                inp = os.path.join(work, "inputs", cid + ".tif")
                V.make_voided(tp, inp, kind, seed)
                cases.append((cid, dem, kind, seed, inp, tp))
    if "realvoids" in a.kinds:
        for host in a.hosts:
            tp = truth_path(host, work)
            for mask in REAL_MASKS:
                for seed in range(a.seeds):
                    cid = f"{host}__{mask}__s{seed}"
                    inp = os.path.join(work, "inputs", cid + ".tif")
                    V.make_voided(tp, inp, "realvoids", seed,
                                  punch_fn=lambda src, m=mask, s=seed: real_mask(m, s, src.shape) & src.valid(),
                                  tag=f"{mask}-{seed}")
                    cases.append((cid, f"{host} × {mask}", "realvoids", seed, inp, tp))
    return cases


def main(argv=None):
    a = parse_args(argv)
    t_start = time.time()
    work = a.work
    V.make_work_dirs(work)

    ok, msg = V.mcmd_status(a.mcmd)
    methods = list(a.methods)
    skipped = []
    if not ok:
        skipped = [m for m in methods if m in V.MCMD_METHODS]
        methods = [m for m in methods if m not in V.MCMD_METHODS]
        log("WARNING: " + msg)
        if skipped:
            log("WARNING: not run: " + ", ".join(skipped))
    run_key = V.run_key(a.mcmd)
    peer_key = P.peer_key()

    for tool in ("grass", "saga"):
        usable, why = P.available(tool)
        if not usable:
            gone = [m for m in methods if m.startswith(tool + "-")]
            methods = [m for m in methods if m not in gone]
            skipped += gone
            log(f"WARNING: {why}; not run: {', '.join(gone)}")

    cases = truth_cases(a, work)   # (case_id, dem, kind, seed, input, truth or None)
    for dem in a.reals:
        cases.append((f"{dem}__real", dem, "real", 0,
                      os.path.join(V.DEM_DIR, dem + ".tif"), None))

    log(f"accuracy: {len(cases)} cases x {len(methods)} methods "
        f"({', '.join(methods)}); work in {work}")
    results = {}   # (cid, method) -> result dict
    for i, (cid, dem, kind, seed, inp, tp) in enumerate(cases):
        log(f"[{i + 1}/{len(cases)}] {cid}")
        w, h = V.raster_size(inp)
        inr = V.read_raster(inp)
        removed = ~inr.valid()
        truth = V.read_raster(tp).data if tp else None

        def evaluate(out_path, removed=removed, truth=truth, inr=inr):
            return V.score_fill(out_path, inr, removed, truth)

        specs = []
        peer_case = (kind == "real" and not a.quick) if kind == "real" else (a.peer_seeds is None or seed < a.peer_seeds)
        case_methods = [m for m in methods if peer_case or m not in P.PEERS]
        for m in case_methods:
            out = os.path.join(work, "out", f"{cid}__{m}.tif")
            res = os.path.join(work, "results", f"{cid}__{m}.json")
            if m in P.PEERS:
                cmd = [sys.executable, os.path.join(V.BENCH_DIR, "peers.py"), m, inp, out]
                specs.append(V.FillSpec(res, cmd, out, a.timeout_peers, evaluate))
            else:
                cmd = V.fill_cmd(m, inp, out, max(w, h), a.mcmd, seed=seed)
                specs.append(V.FillSpec(res, cmd, out, a.timeout, evaluate))
        # mcmd's and GDAL's fills of the case in interleaved rounds, so that
        # time ratios compare runs of the same minutes; each peer on its own
        # (cached under the tools' versions, not mcmd's binary: they take
        # seconds to minutes, far beyond the timing noise).
        own = [(m, sp) for m, sp in zip(case_methods, specs) if m not in P.PEERS]
        for m, r in zip([m for m, _ in own],
                        V.cached_fills([sp for _, sp in own], run_key, force=a.force, log=log,
                                       repeat=a.repeat, mem_limit_mb=a.mem_limit_mb or None)):
            results[(cid, m)] = r
        for m, sp in zip(case_methods, specs):
            if m in P.PEERS:
                if a.cached_peers:
                    r = V.load_json(sp.res_path)
                    if r and r.get("key") == sp.full_key(peer_key):
                        results[(cid, m)] = r
                    continue
                results[(cid, m)] = V.cached_fills([sp], peer_key, force=a.force, log=log,
                                                   repeat=a.repeat_peers,
                                                   mem_limit_mb=a.mem_limit_mb or None)[0]

    pngs = {} if a.no_png else make_pngs(a, cases, methods, work)
    R.write_report(a, cases, methods, skipped, results, pngs, msg if not ok else None)
    log(f"wrote {a.out} ({time.time() - t_start:.0f} s)")
    return 0


def make_pngs(a, cases, methods, work):
    """Hillshades (input, truth, every fill) of the largest void, for blobs
    and big seed 0 per DEM and for each real-void tile."""
    out = {}
    os.makedirs(a.png_dir, exist_ok=True)
    for cid, dem, kind, seed, inp, tp in cases:
        if not ((kind in ("blobs", "big") and seed == 0) or kind == "real"):
            continue
        inr = V.read_raster(inp)
        bbox = V.largest_void_bbox(~inr.valid())
        if bbox is None:
            continue
        main, detail = V.void_window(bbox, inr.shape, void=~inr.valid(), data=inr.data)
        panels = [("input", inp)]
        if tp:
            panels.append(("truth", tp))
        for m in methods:
            p = os.path.join(work, "out", f"{cid}__{m}.tif")
            if os.path.exists(p):
                panels.append((m, p))
        name = {"blobs": dem, "big": dem + "__big"}.get(kind, dem + "__real")
        row = []
        for label, src in panels:
            png = os.path.join(a.png_dir, f"{name}__{label}.png")
            try:
                V.hillshade_png(src, main, png)
                row.append((label, png))
            except Exception as e:  # noqa: BLE001
                log(f"  hillshade failed for {src}: {e}")
        out[cid] = {"window": main, "bbox": bbox, "panels": row}
    return out


if __name__ == "__main__":
    sys.exit(main())
