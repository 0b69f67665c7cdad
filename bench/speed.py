#!/usr/bin/python3
"""Speed and memory benchmark: mcmd_fillnodata vs gdal_fillnodata.

On ../shared/dem files with voids punched in (kept3: a random 3.3 % of cells
kept; blobs: ~5 % of the area in blob voids), from 465x457 to the 4801^2 and
10801x4801 mosaics, and on the real-void SRTM tiles (incl. the half-void
3601^2 tile), runs ``mcmd_fillnodata`` with default settings, with
``-threads 1``, and ``gdal_fillnodata.py -md <max(W,H)> -si 2`` in the same
run (one after the other, per file). Records whole-process wall time and
peak RSS (``/usr/bin/time -v``), RMSE against the original where there is
one, completeness, whether known cells are bit-exact, the speed-up, and a
hillshade PNG of the largest filled void. Also: ``-threads 1`` vs
``-threads 2`` pixel md5 on a few files, and RMSE with ``-tile 257`` vs the
default tile size on every blob case. Writes bench/RESULTS.md and
bench/speed/*.png.

Resumable: each (case, run) result is cached as JSON under
bench/work/speed/results/ and redone only when the mcmd binary (or GDAL) or
the command line changes, or with --force.

    /usr/bin/python3 bench/speed.py [--mcmd build/bin/mcmd_fillnodata]
    /usr/bin/python3 bench/speed.py --quick           # smoke run, < 1 min
"""

from __future__ import annotations

import os
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import voids as V  # noqa: E402

# (DEM, void kinds), smallest first
TRUTH_CASES = [
    ("srtm3_zion", ("kept3", "blobs")),
    ("nasadem3_mt_washington_513", ("kept3", "blobs")),
    ("srtm30m_big_tujunga_utm11", ("kept3", "blobs")),
    ("ned1_half_dome_float32", ("kept3", "blobs")),
    ("nasadem3_N44W072_white_mountains", ("kept3", "blobs")),
    ("ferranti3_sierra_nevada_4801", ("blobs", "kept3")),
    ("ferranti3_california_nevada_10801x4801", ("blobs", "kept3")),
]
REAL_CASES = ["srtm3_N42E001_pyrenees_voids", "srtm3_N43E007_alpes_maritimes_voids",
              "srtm1_N48W125_halfvoid_3601"]
BIG = "ferranti3_california_nevada_10801x4801"
ROUGH_CASES = (f"{BIG}__blobs", f"{BIG}__kept3")  # -rs auto timed beside the smooth fill
MID = "ferranti3_sierra_nevada_4801"
HALF = "srtm1_N48W125_halfvoid_3601"
# files where -threads 2 is also run and its md5 compared with -threads 1
DET_CASES = [f"{MID}__blobs", f"{HALF}__real"]
SMALL_CELLS = 2_000_000  # rasters up to this many cells get --small-repeat rounds

RUNS = {            # name -> extra mcmd args (None = gdal, "floor" = gdal_translate)
    "mcmd": [],
    "mcmd-t1": ["-threads", "1"],
    "gdal-si2": None,
    "floor": "floor",
}
LABEL = {"mcmd": "mcmd (default)", "mcmd-t1": "mcmd -threads 1", "gdal-si2": "gdal -si 2",
         "floor": "gdal_translate (I/O floor)",
         "mcmd-t2": "mcmd -threads 2", "mcmd-tile257": "mcmd -tile 257", "mcmd-rs-auto": "mcmd -rs auto"}


log = V.log


def parse_args(argv=None):
    ap = V.common_parser(__doc__, "smoke run: zion (kept3, blobs) + the alpes-maritimes tile; writes "
                         "bench/work/RESULTS-quick.md, not bench/RESULTS.md", "restrict to files whose name contains this (repeatable)")
    ap.add_argument("--kinds", default="kept3,blobs,real",
                    help="case kinds to run (kept3,blobs,real)")
    ap.add_argument("--no-big-kept3", action="store_true",
                    help="skip kept3 on the 10801x4801 mosaic")
    ap.add_argument("--runs", default=",".join(RUNS),
                    help="which of the main runs to do (default: " + ",".join(RUNS) + ")")
    ap.add_argument("--seed", type=int, default=0)
    ap.add_argument("--timeout-gdal", type=float, default=900,
                    help="per-run timeout for gdal_fillnodata, s (900); a timeout is "
                         "recorded as '> N s'")
    ap.add_argument("--timeout-mcmd", type=float, default=900,
                    help="per-run timeout for mcmd_fillnodata, s (900)")
    ap.add_argument("--no-extras", action="store_true",
                    help="skip the -threads 2 md5 and -tile 257 RMSE checks")
    ap.add_argument("--repeat", type=int, default=3,
                    help="runs per fill, interleaved; the median times are reported (3)")
    ap.add_argument("--small-repeat", type=int, default=11,
                    help="rounds for the rasters of at most 2 million cells (at least --repeat): "
                         "their runs take a tenth of a second and vary by a third from run to run (11)")
    ap.add_argument("--rs-repeat", type=int, default=7,
                    help="rounds for the cases whose -rs auto cost is compared with the smooth fill's "
                         "(the mosaics; at least --repeat): a ratio of two noisy times (7)")
    ap.add_argument("--keep", action="store_true", help="keep output rasters in the work dir")
    ap.add_argument("--work", default=None,
                    help="work folder (default bench/work/speed, or bench/work/speed-quick)")
    ap.add_argument("--out", default=None, help="markdown file (default bench/RESULTS.md)")
    ap.add_argument("--png-dir", default=None, help="PNG folder (default bench/speed)")
    ap.add_argument("--no-png", action="store_true")
    a = ap.parse_args(argv)
    a.kinds = [k.strip() for k in a.kinds.split(",") if k.strip()]
    a.runs = [r.strip() for r in a.runs.split(",") if r.strip()]
    for r in a.runs:
        if r not in RUNS:
            ap.error(f"unknown run {r!r}")
    cases = []   # (case_id, dem, kind)
    for dem, kinds in TRUTH_CASES:
        for k in kinds:
            if k in a.kinds and not (dem == BIG and k == "kept3" and a.no_big_kept3):
                cases.append((f"{dem}__{k}", dem, k))
    if "real" in a.kinds:
        cases += [(f"{d}__real", d, "real") for d in REAL_CASES]
    if a.quick:
        cases = [c for c in cases if c[1] in ("srtm3_zion", "srtm3_N43E007_alpes_maritimes_voids")]
        a.out = a.out or os.path.join(V.BENCH_DIR, "work", "RESULTS-quick.md")
        a.png_dir = a.png_dir or os.path.join(V.BENCH_DIR, "work", "speed-quick")
    if a.only:
        cases = [c for c in cases if any(o in c[0] for o in a.only)]
    a.cases = cases
    a.out = a.out or os.path.join(V.BENCH_DIR, "RESULTS.md")
    a.png_dir = a.png_dir or os.path.join(V.BENCH_DIR, "speed")
    a.work = a.work or os.path.join(V.BENCH_DIR, "work", "speed" + ("-quick" if a.quick else ""))
    a.mcmd = os.path.abspath(a.mcmd)
    return a


def main(argv=None):
    a = parse_args(argv)
    t_start = time.time()
    work = a.work
    V.make_work_dirs(work)
    os.makedirs(a.png_dir, exist_ok=True)

    ok, msg = V.mcmd_status(a.mcmd)
    runs = {k: v for k, v in RUNS.items() if k in a.runs}
    if not ok:
        log("WARNING: " + msg)
        runs = {k: v for k, v in runs.items() if v is None or v == "floor"}
    run_key = V.run_key(a.mcmd)

    results = {}   # (cid, run) -> dict
    infos = {}
    log(f"speed: {len(a.cases)} cases x runs {', '.join(runs)}; work in {work}")
    for i, (cid, dem, kind) in enumerate(a.cases):
        log(f"[{i + 1}/{len(a.cases)}] {cid}")
        src = os.path.join(V.DEM_DIR, dem + ".tif")
        if kind == "real":
            inp, truth_path = src, None
            w, h = V.raster_size(inp)
            info = {"width": w, "height": h}
        else:
            inp = os.path.join(work, "inputs", f"{cid}__s{a.seed}.tif")
            info = V.make_voided(src, inp, kind, a.seed)
            truth_path = src
            w, h = info["width"], info["height"]
        inr = V.read_raster(inp)
        removed = ~inr.valid()
        info["void_cells"] = int(removed.sum())
        info["void_fraction"] = info["void_cells"] / removed.size
        truth = V.read_raster(truth_path).data if truth_path else None
        bbox = V.largest_void_bbox(removed) if kind != "kept3" else None
        win = V.void_window(bbox, removed.shape, void=removed, data=inr.data) if bbox else None
        info["bbox"], info["window"] = bbox, win
        infos[cid] = info
        png = not a.no_png and win is not None
        if png:
            hill(inp, win, os.path.join(a.png_dir, f"{cid}__input"))

        def evaluate(out_path, name, removed=removed, truth=truth, inr=inr, win=win, png=png,
                     cid=cid):
            if name == "floor":  # a copy, not a fill: only its time counts
                os.unlink(out_path)
                return {}
            r = V.score_fill(out_path, inr, removed, truth)
            r["md5"] = V.pixel_md5(out_path) if name.startswith("mcmd") else None
            if png and name in ("mcmd", "gdal-si2", "mcmd-tile257"):
                hill(out_path, win, os.path.join(a.png_dir, f"{cid}__{name}"))
            if not a.keep:
                os.unlink(out_path)
            return r

        todo = list(runs.items())
        if ok and not a.no_extras and "mcmd" in runs:
            if cid in [d for d in DET_CASES] or (a.quick and kind == "blobs"):
                todo.append(("mcmd-t2", ["-threads", "2"]))
            if kind == "blobs":
                todo.append(("mcmd-tile257", ["-tile", "257"]))
            if cid in ROUGH_CASES:  # what roughness costs on the mosaics
                todo.append(("mcmd-rs-auto", ["-rs", "auto"]))
        specs = []
        for name, extra in todo:
            out = os.path.join(work, "out", f"{cid}__{name}.tif")
            if extra == "floor":  # the same input to the same uncompressed GeoTIFF
                cmd = ["gdal_translate", "-q", "-of", "GTiff", inp, out]
                tmo = a.timeout_gdal
            elif extra is None:
                cmd = V.fill_cmd("gdal-si2", inp, out, max(w, h), a.mcmd)
                tmo = a.timeout_gdal
            else:
                cmd = [a.mcmd, "-q"] + extra + [inp, out]
                tmo = a.timeout_mcmd
            res = os.path.join(work, "results", f"{cid}__{name}.json")
            specs.append(V.FillSpec(res, cmd, out, tmo, lambda p, n=name: evaluate(p, n)))
        # The runs of a case in interleaved rounds (GDAL's included): time
        # ratios then compare runs of the same minutes.
        for (name, _), r in zip(todo, V.cached_fills(
                specs, run_key, force=a.force, log=log,
                repeat=rounds(a, w * h, todo),
                mem_limit_mb=a.mem_limit_mb or None)):
            results[(cid, name)] = r
        for sp in specs:
            if not a.keep and os.path.exists(sp.out_path):
                os.unlink(sp.out_path)   # failed runs may leave partial files
    write_report(a, runs, results, infos, None if ok else msg)
    log(f"wrote {a.out} ({time.time() - t_start:.0f} s)")
    return 0


def rounds(a, cells, todo):
    """Interleaved rounds for a case: more on small rasters (noisy tenths of a
    second) and where the -rs auto cost is compared (a ratio of two times)."""
    n = a.repeat
    if cells <= SMALL_CELLS:
        n = max(n, a.small_repeat)
    if any(name == "mcmd-rs-auto" for name, _ in todo):
        n = max(n, a.rs_repeat)
    return n


def hill(src, win, stem):
    """Overview PNG of the window; for a window larger than 256² also a
    full-resolution 256² detail PNG at the void's centre."""
    main, detail = win
    try:
        V.hillshade_png(src, main, stem + ".png")
        if detail:
            V.hillshade_png(src, detail, stem + "__detail.png")
    except Exception as e:  # noqa: BLE001
        log(f"  hillshade failed for {src}: {e}")


# --------------------------------------------------------------------------
# report
# --------------------------------------------------------------------------

def t_str(r):
    if not r:
        return "not run"
    if r.get("timed_out"):
        return f"timeout > {r['timeout_s']:.0f} s"
    if not r.get("ok"):
        return r.get("error", "failed").replace("|", "/")[:60]
    return f"{r['wall_s']:.2f}"


def cpu(r):
    return V.fmt(r.get("cpu_s"), ".2f") if r and r.get("ok") else "—"


def beside_default(a, results, name):
    """(case, default run, `name` run) for the cases where `name` ran."""
    return [(cid, results.get((cid, "mcmd")), results.get((cid, name)))
            for cid, _, _ in a.cases if results.get((cid, name))]


def speedup(r, g):
    if not r or not r.get("ok") or not g:
        return None
    if g.get("timed_out"):
        return f"> {g['timeout_s'] / r['wall_s']:.1f}×"
    if not g.get("ok"):
        return None
    return f"{g['wall_s'] / max(r['wall_s'], 1e-3):.2f}×"


def write_report(a, runs, results, infos, mcmd_msg):
    md_dir = os.path.dirname(os.path.abspath(a.out))
    rel = lambda p: os.path.relpath(p, md_dir)  # noqa: E731
    L = ["# Speed and memory: mcmd_fillnodata vs gdal_fillnodata"
         + (" (QUICK smoke run)" if a.quick else ""), ""]
    L.append(f"Measured on {V.machine_info()}. Every mcmd result here comes from one build "
             "of `mcmd_fillnodata` (results are cached per binary and command line: "
             "bench/README.md).")
    L.append("")
    L.append("Regenerate: `bench/run_speed.sh` (options: `--quick`, `--only NAME`, "
             "`--timeout-gdal S`, `--force`; see bench/README.md).")
    L.append("")
    loads = sorted(x for r in results.values() if r for x in r.get("loads", []))
    if loads:
        L.append(f"The machine is shared: its load average (1 min) when the runs started was "
                 f"{loads[len(loads) // 2]:.1f} (median; {loads[0]:.1f}–{loads[-1]:.1f}) on "
                 f"{os.cpu_count()} cores.")
        L.append("")
    if mcmd_msg:
        L.append(f"**mcmd runs not done:** {mcmd_msg.splitlines()[0]}")
        L.append("")
    L.append("Each file is filled by `mcmd_fillnodata` (default settings; all cores), by "
             "`mcmd_fillnodata -threads 1`, and by `gdal_fillnodata.py -md max(W,H) -si 2`, and "
             "copied by `gdal_translate` to an uncompressed GeoTIFF (the **floor**: reading and "
             f"writing the file), in {a.repeat} interleaved rounds (the medians are shown; "
             f"{max(a.repeat, a.small_repeat)} on the rasters of up to 2 million cells, whose runs "
             "take a tenth of a second and vary by a third from run to run; "
             f"{max(a.repeat, a.rs_repeat)} rounds on the mosaics, whose `-rs auto` time is compared "
             "with the smooth fill's below). "
             "**s** = whole-process wall time, **CPU** = user + system time, **MB** = peak "
             "resident set size, all from `/usr/bin/time -v` (file I/O and interpreter start-up "
             "included). **speed-up** = GDAL's time ÷ mcmd's (wall; CPU; mcmd `-threads 1` wall). "
             "RMSE is over "
             "the removed cells against the original (void-free DEMs with voids punched in: "
             f"kept3 = a random 3.3 % of cells kept; blobs = ~5 % of the area; seed {a.seed}). "
             "Real-void tiles have no truth: completeness only.")
    L.append("")
    L.append("| case | size | void % | mcmd s | mcmd CPU | mcmd MB | -threads 1 s | -threads 1 MB "
             "| gdal s | gdal CPU | gdal MB | floor s | speed-up | speed-up (CPU) | speed-up (1 thread) "
             "| RMSE mcmd | RMSE gdal | RMSE ratio | filled % mcmd / gdal | known cells exact |")
    L.append("|" + "---|" * 20)
    for cid, dem, kind in a.cases:
        info = infos.get(cid, {})
        m, t1, g, fl = (results.get((cid, k)) for k in ("mcmd", "mcmd-t1", "gdal-si2", "floor"))

        def cpu_ratio(r, g):
            ok = r and g and r.get("ok") and g.get("ok") and r.get("cpu_s") and g.get("cpu_s")
            return f"{g['cpu_s'] / r['cpu_s']:.2f}×" if ok else "—"

        def mb(r):
            return V.fmt(r.get("rss_mb"), ".0f") if r and r.get("ok") else "—"

        def rm(r):
            return V.fmt(r.get("rmse"), ".2f") if r and r.get("ok") else "—"

        def comp(r):
            return V.fmt(100 * r["completeness"], ".2f") if r and r.get("ok") and \
                r.get("completeness") is not None else "—"
        rr = None
        if m and g and m.get("ok") and g.get("ok") and m.get("rmse") and g.get("rmse"):
            rr = m["rmse"] / g["rmse"]
        exact = [r.get("known_exact") for r in (m, t1, g) if r and r.get("ok")]
        ex = "—" if not exact else ("yes" if all(exact) else "NO")
        L.append("| " + " | ".join([
            f"{dem} {kind}", f"{info.get('width')}×{info.get('height')}",
            V.fmt(100 * info.get("void_fraction", float("nan")), ".1f"),
            t_str(m), cpu(m), mb(m), t_str(t1), mb(t1), t_str(g), cpu(g), mb(g), t_str(fl),
            speedup(m, g) or "—", cpu_ratio(m, g), speedup(t1, g) or "—",
            rm(m), rm(g), V.fmt(rr, ".3f"), f"{comp(m)} / {comp(g)}", ex]) + " |")
    L.append("")

    # extras
    det = [(cid, results.get((cid, "mcmd-t1")), results.get((cid, "mcmd-t2")),
            results.get((cid, "mcmd"))) for cid, _, _ in a.cases
           if results.get((cid, "mcmd-t2"))]
    if det:
        L.append("## Determinism: `-threads 1` vs `-threads 2` (md5 of the pixel data)")
        L.append("")
        L.append("| case | -threads 1 | -threads 2 | default | identical |")
        L.append("|---|---|---|---|---|")
        for cid, r1, r2, rd in det:
            md = [r.get("md5") if r and r.get("ok") else None for r in (r1, r2, rd)]
            same = md[0] is not None and md[0] == md[1]
            L.append(f"| {cid} | `{md[0]}` | `{md[1]}` | `{md[2]}` | "
                     f"{'yes' if same else 'NO'} |")
        L.append("")
    tile = beside_default(a, results, "mcmd-tile257")
    if tile:
        L.append("## Tile size: `-tile 257` vs default, blob voids (RMSE over removed cells)")
        L.append("")
        L.append("| case | RMSE default | RMSE -tile 257 | ratio | time default s | time -tile 257 s "
                 "| RSS default MB | RSS -tile 257 MB |")
        L.append("|---|---|---|---|---|---|---|---|")
        for cid, rd, rt in tile:
            ok = rd and rt and rd.get("ok") and rt.get("ok") and rd.get("rmse")
            L.append("| " + " | ".join([
                cid, V.fmt(rd.get("rmse") if rd else None, ".3f"),
                V.fmt(rt.get("rmse") if rt else None, ".3f"),
                V.fmt(rt["rmse"] / rd["rmse"] if ok else None, ".4f"),
                t_str(rd), t_str(rt),
                V.fmt(rd.get("rss_mb") if rd else None, ".0f"),
                V.fmt(rt.get("rss_mb") if rt else None, ".0f")]) + " |")
        L.append("")

    rough = beside_default(a, results, "mcmd-rs-auto")
    if rough:
        L.append("## Roughness: `-rs auto` vs the smooth fill")
        L.append("")
        L.append(f"Medians of {max(a.repeat, a.rs_repeat)} interleaved rounds (each round runs every fill "
                 "of the case, GDAL's included): a ratio of two times that each move by ±5 % from run "
                 "to run on this machine.")
        L.append("")
        L.append("| case | smooth s | smooth CPU | -rs auto s | -rs auto CPU | ratio (wall) | RMSE smooth "
                 "| RMSE -rs auto |")
        L.append("|---|---|---|---|---|---|---|---|")
        for cid, rd, rr in rough:
            okr = rd and rr and rd.get("ok") and rr.get("ok")
            L.append("| " + " | ".join([
                cid, t_str(rd), cpu(rd), t_str(rr), cpu(rr),
                V.fmt(rr["wall_s"] / rd["wall_s"] if okr else None, ".2f") + "×",
                V.fmt(rd.get("rmse") if rd else None, ".3f"),
                V.fmt(rr.get("rmse") if rr else None, ".3f")]) + " |")
        L.append("")

    chk = done_checks(a, results, tile, det, rough)
    if chk:
        L.append("## Targets (checked automatically)")
        L.append("")
        L.append("| check | value | target | pass |")
        L.append("|---|---|---|---|")
        L.extend(chk)
        L.append("")

    if not a.no_png:
        L.append("## Hillshades of the largest filled void")
        L.append("")
        L.append("gdaldem hillshade of a window around the largest void (≤ 256² PNG; larger "
                 "windows are averaged down, with a full-resolution 256² detail on the void "
                 "border where the terrain around it has most relief). Black = nodata.")
        L.append("")
        for cid, dem, kind in a.cases:
            panels = []
            for name in ("input", "mcmd", "gdal-si2", "mcmd-tile257"):
                for suf in ("", "__detail"):
                    p = os.path.join(a.png_dir, f"{cid}__{name}{suf}.png")
                    if os.path.exists(p):
                        panels.append((LABEL.get(name, name) + (" (detail)" if suf else ""), p))
            if not panels:
                continue
            info = infos.get(cid, {})
            L.append(f"**{cid}** — largest void bbox {info.get('bbox')}")
            L.append("")
            L.append("| " + " | ".join(lbl for lbl, _ in panels) + " |")
            L.append("|" + "---|" * len(panels))
            L.append("| " + " | ".join(f"![{lbl}]({rel(p)})" for lbl, p in panels) + " |")
            L.append("")

    L.append("## All runs")
    L.append("")
    L.append("| case | run | status | wall s | user s | sys s | RSS MB | RMSE | max err | filled % |")
    L.append("|---|---|---|---|---|---|---|---|---|---|")
    for cid, _, _ in a.cases:
        for name in ("mcmd", "mcmd-t1", "mcmd-t2", "mcmd-tile257", "gdal-si2"):
            r = results.get((cid, name))
            if not r:
                continue
            st = "ok" if r.get("ok") else r.get("error", "failed").replace("|", "/")[:80]
            comp = r.get("completeness")
            L.append("| " + " | ".join([
                cid, LABEL[name], st, V.fmt(r.get("wall_s"), ".2f"), V.fmt(r.get("user_s"), ".2f"),
                V.fmt(r.get("sys_s"), ".2f"), V.fmt(r.get("rss_mb"), ".0f"),
                V.fmt(r.get("rmse"), ".3f"), V.fmt(r.get("max_err"), ".1f"),
                V.fmt(100 * comp if comp is not None else None, ".2f")]) + " |")
    L.append("")
    with open(a.out, "w") as f:
        f.write("\n".join(L))


def done_checks(a, results, tile, det, rough):
    rows = []

    def row(name, val, target, ok):
        rows.append(f"| {name} | {val} | {target} | {'yes' if ok else 'NO'} |")

    ok = lambda r: bool(r and r.get("ok"))  # noqa: E731
    big = results.get((f"{BIG}__blobs", "mcmd"))
    mid = results.get((f"{MID}__blobs", "mcmd"))
    if ok(big):
        c = big.get("completeness", 0)
        row("10801×4801 blobs: filled completely", f"{100 * c:.3f} %", "100 %", c == 1.0)
        row("10801×4801 blobs: valid cells bit-exact", str(big.get("known_exact")), "True",
            bool(big.get("known_exact")))
        floor = results.get((f"{BIG}__blobs", "floor"))
        if ok(floor):
            q = big["wall_s"] / floor["wall_s"]
            row("10801×4801 blobs: time ÷ gdal_translate floor", f"{q:.1f}×", "≤ 3×", q <= 3)
        if ok(mid):
            q = big["rss_mb"] / mid["rss_mb"]
            row("peak RSS 10801×4801 ÷ 4801², blobs", f"{q:.2f}", "≤ 1.25", q <= 1.25)
    # The large cases: faster than GDAL in wall and CPU time, one thread at least as fast.
    wall_target = {f"{BIG}__kept3": 1.5, f"{BIG}__blobs": 4.0, f"{MID}__blobs": 4.0}
    for cid in (f"{MID}__blobs", f"{MID}__kept3", f"{BIG}__blobs", f"{BIG}__kept3", f"{HALF}__real"):
        m, t1, g = (results.get((cid, k)) for k in ("mcmd", "mcmd-t1", "gdal-si2"))
        if not (ok(m) and ok(g)):
            continue
        want = wall_target.get(cid, 1.0)
        q = g["wall_s"] / m["wall_s"]
        row(f"{cid}: speed-up vs GDAL (wall)", f"{q:.2f}×", f"≥ {want:g}×" if want > 1 else "> 1×",
            q >= want if want > 1 else q > 1)
        if m.get("cpu_s") and g.get("cpu_s"):
            q = g["cpu_s"] / m["cpu_s"]
            row(f"{cid}: speed-up vs GDAL (CPU)", f"{q:.2f}×", "> 1×", q > 1)
        if ok(t1):
            q = g["wall_s"] / t1["wall_s"]
            row(f"{cid}: -threads 1 vs GDAL (wall)", f"{q:.2f}×", "≥ 1×", q >= 1)
        row(f"{cid}: peak RSS", f"{m['rss_mb']:.0f} MB", "< 512 MB", m["rss_mb"] < 512)
    hv = results.get((f"{HALF}__real", "mcmd"))
    if hv and hv.get("ok"):
        c = hv.get("completeness", 0)
        row("half-void 3601² filled completely", f"{100 * c:.3f} %", "100 %", c == 1.0)
    for cid, rd, rt in tile:
        if rd and rt and rd.get("ok") and rt.get("ok") and rd.get("rmse"):
            q = rt["rmse"] / rd["rmse"]
            row(f"-tile 257 vs default RMSE, {cid}", f"{q:.4f}", "within 3 %", abs(q - 1) <= 0.03)
    for cid, r1, r2, _ in det:
        if r1 and r2 and r1.get("ok") and r2.get("ok"):
            row(f"-threads 1 == -threads 2, {cid}", "identical" if r1["md5"] == r2["md5"]
                else "differ", "identical", r1["md5"] == r2["md5"])
    for cid, rd, rr in rough:
        if ok(rd) and ok(rr):
            q = rr["wall_s"] / rd["wall_s"]
            row(f"-rs auto ÷ smooth (wall), {cid}", f"{q:.2f}×", "≤ 1.10×", q <= 1.10)
    return rows


if __name__ == "__main__":
    sys.exit(main())
