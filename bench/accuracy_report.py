"""The Markdown report of the accuracy benchmark (bench/accuracy.py):
summaries per void kind, the targets checked, which tool wins where, per-case
RMSE, the real-void tiles, hillshades and every run."""

from __future__ import annotations

import os

import peers as P
import voids as V

REF = "gdal-si2"
LABEL = {
    "mcmd": "mcmd", "mcmd-rs-auto": "mcmd -rs auto", "paper-ds": "paper-ds",
    "paper-te": "paper-te", "gdal-si0": "gdal -si 0", "gdal-si2": "gdal -si 2", **P.LABEL,
}
KIND_TEXT = {
    "kept3": "a random 3.3 % of the cells kept, the rest removed (the MCMD paper's experiment)",
    "blobs": "a union of smooth random blobs (one large, many small, some touching the border) "
             "covering ~5 % of the area",
    "big": "one smooth blob about a quarter of the raster's width across",
    "realvoids": "the void masks of the two real-void SRTM tiles (Pyrenees: 7652 cells in 671 "
                 "voids, the largest 1417; Alpes-Maritimes: 1595 cells in 130 voids) laid onto "
                 "void-free 1201² mountain DEMs (White Mountains; a Sierra Nevada crop of the 3\" "
                 "mosaic at x 3800, y 2500), as they are (seed 0), mirrored left-right (1) or "
                 "turned half a turn (2)",
}
# The default's peers in the targets: every tool a GIS user has at hand.
PEER_ROWS = ["gdal-si0", "gdal-si2"] + [p for p in P.PEERS if p != "grass-rst-stock"]
READING = os.path.join(V.BENCH_DIR, "ACCURACY-reading.md")


def ratio(r, ref, key):
    if not r or not ref or not r.get("ok") or not ref.get("ok"):
        return None
    x, y = r.get(key), ref.get(key)
    if x is None or y is None or y == 0:
        return None
    return x / y


def kind_cases(cases, kind):
    return [c for c in cases if c[2] == kind]


def med_ratio(results, kc, m, key="rmse"):
    return V.median([ratio(results.get((c[0], m)), results.get((c[0], REF)), key) for c in kc])


def header(a, L, mcmd_msg):
    L.append("# Accuracy: mcmd vs gdal_fillnodata, GRASS r.fillnulls and SAGA Close Gaps"
             + (" (QUICK smoke run)" if a.quick else ""))
    L.append("")
    L.append(f"Measured on {V.machine_info()}. Every mcmd result here comes from one build "
             "of `mcmd_fillnodata` (results are cached per binary and command line: "
             "bench/README.md).")
    L.append("")
    L.append("Regenerate: `bench/run_accuracy.sh` (options: `--quick`, `--only DEM`, "
             "`--methods m1,m2`, `--kinds k1,k2`, `--force`; see bench/README.md).")
    L.append("")
    if mcmd_msg:
        L.append(f"**mcmd methods not run:** {mcmd_msg.splitlines()[0]}")
        L.append("")
    L.append("Void kinds: " + "; ".join(f"**{k}** = {KIND_TEXT[k]}" for k in a.kinds) +
             f". Seeds 0..{a.seeds - 1}. Every fill is scored on the removed cells only: "
             "RMSE and max |error| against the original; **lap** = std of the 5-point "
             "Laplacian of the fill ÷ the same for the truth (1 = as rough as the terrain, "
             "0.2 = much too smooth); **slope** = mean gradient magnitude of the fill ÷ truth. "
             "Ratios \"/gdal\" are to `gdal_fillnodata.py -md max(W,H) -si 2` on the same case; "
             "**time** is whole-process wall time, file I/O included, and **RSS** the peak "
             "resident memory (`/usr/bin/time -v`, the largest process of the run). mcmd's and "
             "GDAL's fills of a case run in interleaved rounds (median of `--repeat`) so that "
             "they are timed in the same minutes; GRASS and SAGA run once per case.")
    L.append("")
    L.append("The peers (`bench/peers.py`, every option at its default): GRASS 8.2 "
             "`r.fillnulls` with method **rst** (the regularised spline with tension, fitted "
             "per hole to the known cells within 3 cells of it: tension 40, smoothing 0.1), "
             "**bicubic** and **bilinear** (`r.resamp.bspline` over the whole raster, steps of 3 "
             "cells, λ 0.01), each in a temporary GRASS location (`grass --tmp-location XY "
             "--exec`); SAGA 8.5 `saga_cmd grid_tools` **Close Gaps** (7), **Close Gaps with "
             "Spline** (25) and **Close Gaps with Stepwise Resampling** (29). GRASS gets the "
             "raster's own grid with its cells' size in metres (a geographic raster as a local "
             "metric grid: the same cells, isotropic distances, as a projected CRS gives); SAGA "
             "gets the raster as it is (its grids need square cells, which geographic cells are "
             "in degrees, not in metres). Every output is checked to lie on the input's grid "
             "before it is scored. GRASS 8.2.1's "
             "`r.fillnulls method=rst` fails on every geographic raster (`ERROR: Invalid input "
             "<n=n+0>`: it grows each hole's region by `\"%d\" % (edge·2·resolution)`, 0 for cells "
             "a fraction of a degree wide); and it runs ~12 GRASS modules per hole (~2 s each "
             "hole, 15–30 min on the real-void masks). The rst row is therefore `peers.py`'s own "
             "loop over r.fillnulls' holes (the same holes, edge points, region, tension, "
             "smoothing, segmax and npmin, one `v.surf.rst` per hole): on a projected raster, "
             "where `r.fillnulls` runs, both give bit-identical fills, ours in a fifth of the "
             "time; its times here are thus below what `r.fillnulls` takes.")
    L.append("")


def summaries(a, L, truth, mlist, results):
    for kind in a.kinds:
        kc = kind_cases(truth, kind)
        if not kc:
            continue
        L.append(f"## Summary — {kind} (medians over {len(kc)} cases)")
        L.append("")
        L.append("| method | cases ok | RMSE m | RMSE /gdal | worst RMSE /gdal | max err /gdal "
                 "| lap | slope | time s | CPU s | time /gdal | worst time /gdal | RSS MB |")
        L.append("|---|---|---|---|---|---|---|---|---|---|---|---|---|")
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
                V.fmt(V.median([r.get("cpu_s") for r in good]), ".2f"),
                V.fmt(V.median(tr), ".2f"), V.fmt(wt, ".2f"),
                V.fmt(V.median([r.get("rss_mb") for r in good]), ".0f")]) + " |")
        L.append("")


def wins(a, L, truth, mlist, results):
    """Per void kind, how many cases each tool fills best (lowest RMSE of all
    rows; paper methods and -rs auto count as rows too), over the cases every
    row ran on (the peers may have run on fewer)."""
    rows = []
    for kind in a.kinds:
        kc = [c for c in kind_cases(truth, kind) if all(results.get((c[0], m)) for m in mlist)]
        if not kc:
            continue
        count = {m: 0 for m in mlist}
        for c in kc:
            best = None
            for m in mlist:
                r = results.get((c[0], m))
                if r and r.get("ok") and r.get("rmse") is not None and (best is None or r["rmse"] < best[1]):
                    best = (m, r["rmse"])
            if best:
                count[best[0]] += 1
        rows.append((kind, len(kc), count))
    if not rows:
        return
    L.append("## Who fills best (cases with the lowest RMSE of all rows, over the cases "
             "every row ran on)")
    L.append("")
    L.append("| kind | cases | " + " | ".join(LABEL[m] for m in mlist) + " |")
    L.append("|---|---|" + "---|" * len(mlist))
    for kind, n, count in rows:
        L.append(f"| {kind} | {n} | " + " | ".join(str(count[m]) if count[m] else "·" for m in mlist) + " |")
    L.append("")


def reading(L):
    if os.path.exists(READING):
        with open(READING) as f:
            text = f.read().strip()
        if text:
            L.append(text)
            L.append("")


def per_case(a, L, truth, mlist, results):
    for kind in a.kinds:
        kc = kind_cases(truth, kind)
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


def real_tiles(L, cases, mlist, results):
    real = [c for c in cases if c[2] == "real"]
    if not real:
        return
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


def gallery(L, pngs, rel):
    if not pngs:
        return
    L.append("## Hillshades of the largest void (blobs and big seed 0; real-void tiles)")
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


def all_runs(L, cases, mlist, results):
    L.append("## All runs")
    L.append("")
    L.append("| case | method | RMSE | max err | bias | lap | slope | filled % | time s | CPU s | RSS MB "
             "| status |")
    L.append("|---|---|---|---|---|---|---|---|---|---|---|---|")
    for c in cases:
        for m in mlist:
            r = results.get((c[0], m))
            if not r:
                L.append(f"| {c[0]} | {LABEL[m]} | | | | | | | | | | not run |")
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
                V.fmt(r.get("wall_s"), ".2f"), V.fmt(r.get("cpu_s"), ".2f"),
                V.fmt(r.get("rss_mb"), ".0f"), st]) + " |")
    L.append("")


def write_report(a, cases, methods, skipped, results, pngs, mcmd_msg):
    L = []
    md_dir = os.path.dirname(os.path.abspath(a.out))
    rel = lambda p: os.path.relpath(p, md_dir)  # noqa: E731
    mlist = methods + [m for m in skipped if m not in methods]
    truth = [c for c in cases if c[2] != "real"]
    header(a, L, mcmd_msg)
    summaries(a, L, truth, mlist, results)
    chk = done_checks(a, truth, results)
    if chk:
        L.append("## Targets (checked automatically)")
        L.append("")
        L.append("| check | value | target | pass |")
        L.append("|---|---|---|---|")
        L.extend(chk)
        L.append("")
    wins(a, L, truth, mlist, results)
    reading(L)
    per_case(a, L, truth, mlist, results)
    real_tiles(L, cases, mlist, results)
    gallery(L, pngs, rel)
    all_runs(L, cases, mlist, results)
    os.makedirs(md_dir, exist_ok=True)
    with open(a.out, "w") as f:
        f.write("\n".join(L))


def done_checks(a, truth, results):
    rows = []

    def allr(m, key, kc=truth):
        return [(c[0], ratio(results.get((c[0], m)), results.get((c[0], REF)), key)) for c in kc]

    def row(name, val, target, ok):
        rows.append(f"| {name} | {val} | {target} | {'yes' if ok else 'NO'} |")

    if not any(results.get((c[0], "mcmd"), {}).get("ok") for c in truth):
        return rows
    for kind in a.kinds:
        kc = kind_cases(truth, kind)
        v = med_ratio(results, kc, "mcmd")
        if v is None:
            continue
        if kind in ("kept3", "blobs"):
            row(f"mcmd median RMSE /gdal, {kind}", f"{v:.3f}", "≤ 0.75", v <= 0.75)
        # Each peer against mcmd on the cases both filled (peers may run on
        # fewer seeds: --peer-seeds).
        worst = None   # the peer with the smallest margin: (margin, peer, mcmd m, peer m, cases)
        for m in PEER_ROWS:
            both = [c for c in kc if (results.get((c[0], m)) or {}).get("ok")
                    and (results.get((c[0], "mcmd")) or {}).get("ok")]
            if not both:
                continue
            mine = V.median([results[(c[0], "mcmd")]["rmse"] for c in both])
            theirs = V.median([results[(c[0], m)]["rmse"] for c in both])
            if worst is None or theirs - mine < worst[0]:
                worst = (theirs - mine, m, mine, theirs, len(both))
        if worst:
            _, m, mine, theirs, n = worst
            row(f"mcmd median RMSE ≤ every peer's, {kind}",
                f"closest: {LABEL[m]} {theirs:.2f} m against mcmd {mine:.2f} m ({n} cases)", "≤",
                mine <= theirs)
    rr = [(cid, x) for cid, x in allr("mcmd", "rmse") if x is not None]
    if rr:
        cid, x = max(rr, key=lambda t: t[1])
        row("mcmd worst case RMSE /gdal", f"{x:.3f} ({cid})", "≤ 1.0", x <= 1.0)
    auto = [results.get((c[0], "mcmd-rs-auto")) for c in truth]
    if any(r and r.get("ok") for r in auto):
        v = V.median([x for _, x in allr("mcmd-rs-auto", "rmse")])
        if v is not None:
            row("mcmd -rs auto median RMSE /gdal (all cases)", f"{v:.3f}", "≤ 0.90", v <= 0.90)
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
