#!/usr/bin/python3
"""Accuracy benchmark: mcmd methods vs gdal_fillnodata.

On void-free DEMs from ../shared/dem with voids punched in (kept3: a random
3.3 % of cells kept; blobs: ~5 % of the area in blob voids) x 3 seeds, plus
the real-void SRTM tiles, runs every mcmd method and
``gdal_fillnodata.py -md <max(W,H)> -si 0`` and ``-si 2`` in the same run,
and records RMSE, max error, Laplacian-spread and mean-slope ratios inside the
voids, whole-process time, and hillshade PNGs of the largest void.
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

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
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

ALL_METHODS = ["mcmd", "mcmd-rs-auto", "paper-ds", "paper-te", "gdal-si0", "gdal-si2"]
REF = "gdal-si2"
LABEL = {
    "mcmd": "mcmd", "mcmd-rs-auto": "mcmd -rs auto", "paper-ds": "paper-ds",
    "paper-te": "paper-te", "gdal-si0": "gdal -si 0", "gdal-si2": "gdal -si 2",
}


log = V.log


def parse_args(argv=None):
    ap = V.common_parser(__doc__, "smoke run: 1 DEM (513^2), 1 seed, 1 real-void tile; "
                         "writes bench/work/ACCURACY-quick.md, not bench/ACCURACY.md", "restrict to DEMs whose name contains this (repeatable)")
    ap.add_argument("--methods", default=",".join(ALL_METHODS),
                    help="comma list from: " + ",".join(ALL_METHODS))
    ap.add_argument("--kinds", default="kept3,blobs", help="void kinds (kept3,blobs)")
    ap.add_argument("--seeds", type=int, default=3, help="seeds 0..N-1 (default 3)")
    ap.add_argument("--no-extra", action="store_true",
                    help="skip the two extra 1025^2 crops of the 3\" mosaic")
    ap.add_argument("--no-real", action="store_true", help="skip the real-void SRTM tiles")
    ap.add_argument("--timeout", type=float, default=600, help="per-run timeout, s (600)")
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
        if m not in ALL_METHODS:
            ap.error(f"unknown method {m!r}")
    if REF not in a.methods:
        a.methods.append(REF)     # ratios need the reference
    a.kinds = [k.strip() for k in a.kinds.split(",") if k.strip()]
    for k in a.kinds:
        if k not in V.VOID_KINDS:
            ap.error(f"unknown void kind {k!r}")
    if a.quick:
        a.seeds = 1
        dems = ["nasadem3_mt_washington_513"]
        reals = ["srtm3_N43E007_alpes_maritimes_voids"]
        a.out = a.out or os.path.join(V.BENCH_DIR, "work", "ACCURACY-quick.md")
        a.png_dir = a.png_dir or os.path.join(V.BENCH_DIR, "work", "accuracy-quick")
    else:
        dems = [d for d in TRUTH_DEMS if not (a.no_extra and d in EXTRA_DEMS)]
        reals = [] if a.no_real else list(REAL_DEMS)
    if a.only:
        dems = [d for d in TRUTH_DEMS if any(o in d for o in a.only)]
        reals = [] if a.no_real else [d for d in REAL_DEMS if any(o in d for o in a.only)]
    a.dems, a.reals = dems, reals
    a.out = a.out or os.path.join(V.BENCH_DIR, "ACCURACY.md")
    a.png_dir = a.png_dir or os.path.join(V.BENCH_DIR, "accuracy")
    a.work = a.work or os.path.join(V.BENCH_DIR, "work", "accuracy" + ("-quick" if a.quick else ""))
    a.mcmd = os.path.abspath(a.mcmd)
    return a


def truth_path(dem: str, work: str) -> str:
    src, crop = TRUTH_DEMS[dem]
    return V.source_path(src, crop, work, name=dem)


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

    cases = []   # (case_id, dem, kind, seed, input, truth or None)
    for dem in a.dems:
        tp = truth_path(dem, work)
        for kind in a.kinds:
            for seed in range(a.seeds):
                cid = f"{dem}__{kind}__s{seed}"
                inp = os.path.join(work, "inputs", cid + ".tif")
                V.make_voided(tp, inp, kind, seed)
                cases.append((cid, dem, kind, seed, inp, tp))
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
        for m in methods:
            out = os.path.join(work, "out", f"{cid}__{m}.tif")
            cmd = V.fill_cmd(m, inp, out, max(w, h), a.mcmd, seed=seed)
            res = os.path.join(work, "results", f"{cid}__{m}.json")
            specs.append(V.FillSpec(res, cmd, out, a.timeout, evaluate))
        # Every method of the case in interleaved rounds (GDAL included), so
        # that time ratios compare runs of the same minutes.
        for m, r in zip(methods, V.cached_fills(specs, run_key, force=a.force, log=log,
                                                repeat=a.repeat,
                                                mem_limit_mb=a.mem_limit_mb or None)):
            results[(cid, m)] = r

    pngs = {} if a.no_png else make_pngs(a, cases, methods, work)
    write_report(a, cases, methods, skipped, results, pngs, msg if not ok else None)
    log(f"wrote {a.out} ({time.time() - t_start:.0f} s)")
    return 0


def make_pngs(a, cases, methods, work):
    """Hillshades (input, truth, every fill) of the largest void, for blobs
    seed 0 per DEM and for each real-void tile."""
    out = {}
    os.makedirs(a.png_dir, exist_ok=True)
    for cid, dem, kind, seed, inp, tp in cases:
        if not ((kind == "blobs" and seed == 0) or kind == "real"):
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
        name = dem if kind == "blobs" else dem + "__real"
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


# --------------------------------------------------------------------------
# report
# --------------------------------------------------------------------------

def ratio(r, ref, key):
    if not r or not ref or not r.get("ok") or not ref.get("ok"):
        return None
    x, y = r.get(key), ref.get(key)
    if x is None or y is None or y == 0:
        return None
    return x / y


def write_report(a, cases, methods, skipped, results, pngs, mcmd_msg):
    L = []
    md_dir = os.path.dirname(os.path.abspath(a.out))
    rel = lambda p: os.path.relpath(p, md_dir)  # noqa: E731
    L.append("# Accuracy: mcmd vs gdal_fillnodata" + (" (QUICK smoke run)" if a.quick else ""))
    L.append("")
    L.append(f"Measured on {V.machine_info()}. Every mcmd result here comes from one build "
             "of `mcmd_fillnodata` (results are cached per binary and command line: "
             "bench/README.md).")
    L.append("")
    L.append("Regenerate: `bench/run_accuracy.sh` (options: `--quick`, `--only DEM`, "
             "`--methods m1,m2`, `--force`; see bench/README.md).")
    L.append("")
    if mcmd_msg:
        L.append(f"**mcmd methods not run:** {mcmd_msg.splitlines()[0]}")
        L.append("")
    L.append("Void kinds: **kept3** = a random 3.3 % of the cells kept, the rest removed "
             "(the MCMD paper's experiment); **blobs** = union of smooth random blobs "
             "(one large, many small, some touching the border) covering ~5 % of the area. "
             f"Seeds 0..{a.seeds - 1}. Every fill is scored on the removed cells only: "
             "RMSE and max |error| against the original; **lap** = std of the 5-point "
             "Laplacian of the fill ÷ the same for the truth (1 = as rough as the terrain, "
             "0.2 = much too smooth); **slope** = mean gradient magnitude of the fill ÷ truth. "
             "Ratios \"/gdal\" are to `gdal_fillnodata.py -md max(W,H) -si 2` on the same case; "
             "**time** is whole-process wall time (median of `--repeat` runs, the methods of a "
             "case run in interleaved rounds so that mcmd and GDAL are timed in the same "
             "minutes; peak RSS from `/usr/bin/time -v`), file I/O included.")
    L.append("")
    mlist = methods + [m for m in skipped if m not in methods]

    truth_cases = [c for c in cases if c[2] != "real"]
    for kind in a.kinds:
        kc = [c for c in truth_cases if c[2] == kind]
        if not kc:
            continue
        L.append(f"## Summary — {kind} (medians over {len(kc)} cases)")
        L.append("")
        L.append("| method | cases ok | RMSE m | RMSE /gdal | worst RMSE /gdal | max err /gdal "
                 "| lap | slope | time s | time /gdal | worst time /gdal |")
        L.append("|---|---|---|---|---|---|---|---|---|---|---|")
        for m in mlist:
            rs = [results.get((c[0], m)) for c in kc]
            refs = [results.get((c[0], REF)) for c in kc]
            okn = sum(1 for r in rs if r and r.get("ok"))
            rr = [ratio(r, f, "rmse") for r, f in zip(rs, refs)]
            mr = [ratio(r, f, "max_err") for r, f in zip(rs, refs)]
            tr = [ratio(r, f, "wall_s") for r, f in zip(rs, refs)]
            worst = max([x for x in rr if x is not None], default=None)
            wt = max([x for x in tr if x is not None], default=None)
            good = [r for r in rs if r and r.get("ok")]
            L.append("| " + " | ".join([
                LABEL[m], f"{okn}/{len(kc)}",
                V.fmt(V.median([r.get("rmse") for r in good]), ".2f"),
                V.fmt(V.median(rr)), V.fmt(worst), V.fmt(V.median(mr)),
                V.fmt(V.median([r.get("lap_ratio") for r in good]), ".2f"),
                V.fmt(V.median([r.get("slope_ratio") for r in good]), ".2f"),
                V.fmt(V.median([r.get("wall_s") for r in good]), ".2f"),
                V.fmt(V.median(tr), ".2f"), V.fmt(wt, ".2f")]) + " |")
        L.append("")

    # targets
    chk = done_checks(a, truth_cases, results)
    if chk:
        L.append("## Targets (checked automatically)")
        L.append("")
        L.append("| check | value | target | pass |")
        L.append("|---|---|---|---|")
        L.extend(chk)
        L.append("")

    # per-case RMSE tables
    for kind in a.kinds:
        kc = [c for c in truth_cases if c[2] == kind]
        if not kc:
            continue
        L.append(f"## RMSE per case — {kind} (m; ratio to gdal -si 2 in brackets)")
        L.append("")
        L.append("| case | " + " | ".join(LABEL[m] for m in mlist) + " |")
        L.append("|---|" + "---|" * len(mlist))
        for c in kc:
            ref = results.get((c[0], REF))
            cells = []
            for m in mlist:
                cells.append(V.result_cell(results.get((c[0], m)), lambda r: (
                    f"{r['rmse']:.2f} ({V.fmt(ratio(r, ref, 'rmse'), '.2f')})")))
            L.append(f"| {c[1]} s{c[3]} | " + " | ".join(cells) + " |")
        L.append("")

    # real voids
    real = [c for c in cases if c[2] == "real"]
    if real:
        L.append("## Real-void SRTM tiles (no truth: time and completeness)")
        L.append("")
        L.append("| tile | void cells | " + " | ".join(LABEL[m] for m in mlist) + " |")
        L.append("|---|---|" + "---|" * len(mlist))
        for c in real:
            cells, nvoid = [], None
            for m in mlist:
                r = results.get((c[0], m))
                if not r:
                    cells.append("not run")
                elif not r.get("ok"):
                    cells.append(r.get("error", "failed").replace("|", "/")[:60])
                else:
                    nvoid = r.get("n_removed", nvoid)
                    cells.append(f"{r['wall_s']:.2f} s, {100 * r.get('completeness', 0):.2f} % filled")
            L.append(f"| {c[1]} | {nvoid if nvoid is not None else '?'} | " + " | ".join(cells) + " |")
        L.append("")

    # hillshades
    if pngs:
        L.append("## Hillshades of the largest void (blobs seed 0; real-void tiles)")
        L.append("")
        L.append("gdaldem hillshade of a window around the largest void (≤ 256² PNG; a larger "
                 "window is averaged down). Black = nodata. Look for stars (GDAL), dimple "
                 "lattices (paper-ds), straight creases (paper-te), steps at void borders.")
        L.append("")
        for cid, info in pngs.items():
            x, y, w, h = info["window"]
            L.append(f"**{cid}** — window x={x} y={y} {w}×{h}, largest void bbox {info['bbox']}")
            L.append("")
            L.append("| " + " | ".join(LABEL.get(lbl, lbl) for lbl, _ in info["panels"]) + " |")
            L.append("|" + "---|" * len(info["panels"]))
            L.append("| " + " | ".join(f"![{lbl}]({rel(p)})" for lbl, p in info["panels"]) + " |")
            L.append("")

    # full detail
    L.append("## All runs")
    L.append("")
    L.append("| case | method | RMSE | max err | bias | lap | slope | filled % | time s | RSS MB | status |")
    L.append("|---|---|---|---|---|---|---|---|---|---|---|")
    for c in cases:
        for m in mlist:
            r = results.get((c[0], m))
            if not r:
                L.append(f"| {c[0]} | {LABEL[m]} | | | | | | | | | not run |")
                continue
            st = "ok" if r.get("ok") else r.get("error", "failed").replace("|", "/")[:80]
            if r.get("ok") and r.get("known_exact") is False:
                st = "ok, but KNOWN CELLS CHANGED"
            comp = r.get("completeness")
            L.append("| " + " | ".join([
                c[0], LABEL[m], V.fmt(r.get("rmse"), ".3f"), V.fmt(r.get("max_err"), ".1f"),
                V.fmt(r.get("bias"), ".2f"), V.fmt(r.get("lap_ratio"), ".3f"),
                V.fmt(r.get("slope_ratio"), ".3f"),
                V.fmt(100 * comp if comp is not None else None, ".2f"),
                V.fmt(r.get("wall_s"), ".2f"), V.fmt(r.get("rss_mb"), ".0f"), st]) + " |")
    L.append("")
    os.makedirs(md_dir, exist_ok=True)
    with open(a.out, "w") as f:
        f.write("\n".join(L))


def done_checks(a, truth_cases, results):
    rows = []

    def med_ratio(m, kind, key="rmse"):
        kc = [c for c in truth_cases if c[2] == kind]
        return V.median([ratio(results.get((c[0], m)), results.get((c[0], REF)), key) for c in kc])

    def allr(m, key):
        return [(c[0], ratio(results.get((c[0], m)), results.get((c[0], REF)), key))
                for c in truth_cases]

    def row(name, val, target, ok):
        rows.append(f"| {name} | {val} | {target} | {'yes' if ok else 'NO'} |")

    if not any(results.get((c[0], "mcmd"), {}).get("ok") for c in truth_cases):
        return rows
    for kind in a.kinds:
        v = med_ratio("mcmd", kind)
        if v is not None:
            row(f"mcmd median RMSE /gdal, {kind}", f"{v:.3f}", "≤ 0.80", v <= 0.80)
    rr = [(cid, x) for cid, x in allr("mcmd", "rmse") if x is not None]
    if rr:
        cid, x = max(rr, key=lambda t: t[1])
        row("mcmd worst case RMSE /gdal", f"{x:.3f} ({cid})", "≤ 1.05", x <= 1.05)
    auto = [results.get((c[0], "mcmd-rs-auto")) for c in truth_cases]
    if any(r and r.get("ok") for r in auto):
        v = V.median([x for _, x in allr("mcmd-rs-auto", "rmse")])
        if v is not None:
            row("mcmd -rs auto median RMSE /gdal", f"{v:.3f}", "≤ 0.95", v <= 0.95)
        lap = V.median([r.get("lap_ratio") for r in auto if r and r.get("ok")])
        if lap is not None:
            row("mcmd -rs auto median Laplacian spread", f"{lap:.3f}", "0.85 – 1.15",
                0.85 <= lap <= 1.15)
    for m in ("mcmd", "mcmd-rs-auto"):
        tr = [(cid, x) for cid, x in allr(m, "wall_s") if x is not None]
        if tr:
            cid, x = max(tr, key=lambda t: t[1])
            row(f"{LABEL[m]} slowest case time /gdal", f"{x:.2f} ({cid})", "≤ 1 (never slower)",
                x <= 1.0)
    return rows


if __name__ == "__main__":
    sys.exit(main())
