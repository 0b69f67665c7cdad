"""Flow routing for the hydrology benchmark (bench/hydrology.py).

Independent, small implementations (numba-JIT, Debian ``python3-numba``):

* ``priority_flood(z, valid, eps)``: Priority-Flood depression filling
  (Barnes, Lehman & Mulla 2014, "Priority-Flood: An optimal
  depression-filling and watershed-labeling algorithm for digital elevation
  models", Computers & Geosciences 62). Seeds are the valid cells on the
  raster border or 8-adjacent to an invalid (nodata) cell: the raster border
  and every nodata cell are outlets. Without ``eps`` a cell gets
  max(its elevation, the level of the cell that reached it) (plain filling:
  depressions become flat lakes). With ``eps`` (the paper's "+epsilon"
  variant) a cell that would be flat or lower gets the next float64 above
  that level (``nextafter``), so every non-seed cell ends strictly above the
  cell that reached it and drains.
* ``d8_receivers``: steepest-descent (D8) receiver of every cell on an
  epsilon-filled surface; drop / distance, distances from the pixel size.
* ``accumulation``: cells draining through each cell, itself included.
* ``analyse``: all of it plus the channel mask (accumulation >= a fraction
  of the valid cells).
* ``selfcheck``: tiny hand-made grids (a V-valley, a pit, a flat, a closed
  basin, a nodata sink) with known answers, so a broken routine is caught.

Run with /usr/bin/python3 (numpy, numba).
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit

CHANNEL_FRACTION = 0.002     # channel: accumulation >= 0.2 % of the valid cells

# 8-neighbourhood, clockwise from east
DY = np.array([0, 1, 1, 1, 0, -1, -1, -1], dtype=np.int64)
DX = np.array([1, 1, 0, -1, -1, -1, 0, 1], dtype=np.int64)


# --------------------------------------------------------------------------
# a binary min-heap on (level, cell index): deterministic, and the order of
# equal levels does not depend on what was flooded before (a void elsewhere)
# --------------------------------------------------------------------------

@njit(cache=True)
def _less(ka, va, kb, vb):
    return ka < kb or (ka == kb and va < vb)


@njit(cache=True)
def _push(keys, vals, n, k, v):
    i = n
    keys[i] = k
    vals[i] = v
    while i > 0:
        p = (i - 1) >> 1
        if _less(keys[i], vals[i], keys[p], vals[p]):
            keys[i], keys[p] = keys[p], keys[i]
            vals[i], vals[p] = vals[p], vals[i]
            i = p
        else:
            break
    return n + 1


@njit(cache=True)
def _pop(keys, vals, n):
    v = vals[0]
    n -= 1
    keys[0], vals[0] = keys[n], vals[n]
    i = 0
    while True:
        l = 2 * i + 1
        if l >= n:
            break
        m = l
        r = l + 1
        if r < n and _less(keys[r], vals[r], keys[l], vals[l]):
            m = r
        if _less(keys[m], vals[m], keys[i], vals[i]):
            keys[i], keys[m] = keys[m], keys[i]
            vals[i], vals[m] = vals[m], vals[i]
            i = m
        else:
            break
    return v, n


@njit(cache=True)
def _flood(z, valid, eps):
    """Priority-Flood. Returns (level, order): level (NaN on invalid cells)
    and the valid cells' flat indices in the order they were settled
    (non-decreasing level: a valid topological order for draining)."""
    h, w = z.shape
    nv = 0
    for y in range(h):
        for x in range(w):
            if valid[y, x]:
                nv += 1
    level = np.full((h, w), np.nan)
    order = np.empty(nv, dtype=np.int64)
    seen = np.zeros((h, w), dtype=np.bool_)
    keys = np.empty(nv, dtype=np.float64)
    vals = np.empty(nv, dtype=np.int64)
    n = 0
    for y in range(h):
        for x in range(w):
            if not valid[y, x]:
                continue
            seed = y == 0 or x == 0 or y == h - 1 or x == w - 1
            if not seed:
                for k in range(8):
                    if not valid[y + DY[k], x + DX[k]]:
                        seed = True
                        break
            if seed:
                seen[y, x] = True
                level[y, x] = z[y, x]
                n = _push(keys, vals, n, z[y, x], y * w + x)
    # Cells that the current level floods (not above it) go to a FIFO "pit
    # queue" settled before the heap's next cell, as in the paper's improved
    # variant: same levels, far fewer heap operations on flats and lakes.
    pit = np.empty(nv, dtype=np.int64)
    p0 = 0
    p1 = 0
    no = 0
    while n > 0 or p0 < p1:
        if p0 < p1:
            c = pit[p0]
            p0 += 1
        else:
            c, n = _pop(keys, vals, n)
        order[no] = c
        no += 1
        cy, cx = c // w, c % w
        lc = level[cy, cx]
        lup = np.nextafter(lc, np.inf) if eps else lc
        for k in range(8):
            ny, nx = cy + DY[k], cx + DX[k]
            if ny < 0 or nx < 0 or ny >= h or nx >= w:
                continue
            if seen[ny, nx] or not valid[ny, nx]:
                continue
            seen[ny, nx] = True
            zn = z[ny, nx]
            if zn <= lup:
                level[ny, nx] = lup
                pit[p1] = ny * w + nx
                p1 += 1
            else:
                level[ny, nx] = zn
                n = _push(keys, vals, n, zn, ny * w + nx)
    return level, order[:no]


@njit(cache=True)
def _monotone(level_flat, order):
    for i in range(1, order.size):
        if level_flat[order[i]] < level_flat[order[i - 1]]:
            return False
    return True


def priority_flood(z: np.ndarray, valid: np.ndarray, eps: bool = False):
    """(level, order) of Priority-Flood on z (any dtype, as float64);
    ``eps`` = the epsilon variant (see the module doc). ``order``: the valid
    cells by non-decreasing level (so a cell's D8 receiver, strictly lower,
    comes before it)."""
    level, order = _flood(np.ascontiguousarray(z, dtype=np.float64),
                          np.ascontiguousarray(valid, dtype=np.bool_), bool(eps))
    if not _monotone(level.ravel(), order):
        # the pit queue can only break the order if a chain of epsilon steps
        # climbs past a waiting cell's elevation (2^40 steps on integer
        # DEMs); sort then
        order = order[np.argsort(level.ravel()[order], kind="stable")]
    return level, order


@njit(cache=True)
def _d8(level, valid, dist):
    h, w = level.shape
    rcv = np.full(h * w, -1, dtype=np.int64)
    for y in range(h):
        for x in range(w):
            if not valid[y, x]:
                continue
            best = 0.0
            lc = level[y, x]
            for k in range(8):
                ny, nx = y + DY[k], x + DX[k]
                if ny < 0 or nx < 0 or ny >= h or nx >= w or not valid[ny, nx]:
                    continue
                s = (lc - level[ny, nx]) / dist[k]
                if s > best:
                    best = s
                    rcv[y * w + x] = ny * w + nx
    return rcv


def pixel_dist(dx: float = 1.0, dy: float = 1.0) -> np.ndarray:
    """Distances to the 8 neighbours (order of DY/DX) for a dx x dy pixel."""
    d = math.hypot(dx, dy)
    return np.array([dx, d, dy, d, dx, d, dy, d], dtype=np.float64)


def d8_receivers(level: np.ndarray, valid: np.ndarray, dist=None) -> np.ndarray:
    """Flat index of the D8 receiver of every cell (-1: none = an outlet, or
    an invalid cell): the valid neighbour of steepest positive descent."""
    dist = pixel_dist() if dist is None else dist
    return _d8(np.ascontiguousarray(level, dtype=np.float64),
               np.ascontiguousarray(valid, dtype=np.bool_), dist)


@njit(cache=True)
def _accum(rcv, order, size):
    acc = np.zeros(size, dtype=np.int64)
    for i in range(order.size):
        acc[order[i]] = 1
    for i in range(order.size - 1, -1, -1):
        c = order[i]
        r = rcv[c]
        if r >= 0:
            acc[r] += acc[c]
    return acc


def accumulation(rcv: np.ndarray, order: np.ndarray, shape) -> np.ndarray:
    """Cells draining through each cell (itself included); 0 on invalid
    cells. ``order``: cells from lowest to highest level (priority_flood's),
    so every cell comes after its receiver."""
    return _accum(rcv, order, int(shape[0]) * int(shape[1])).reshape(shape)


def analyse(z: np.ndarray, valid: np.ndarray, dist=None,
            channel_fraction: float = CHANNEL_FRACTION, n_ref: int | None = None) -> dict:
    """Plain and epsilon Priority-Flood, D8, accumulation and channels of one
    DEM. ``n_ref``: the cell count the channel threshold is a fraction of
    (default: the valid cells)."""
    zf = np.ascontiguousarray(z, dtype=np.float64)
    plain, _ = priority_flood(zf, valid, eps=False)
    eps, order = priority_flood(zf, valid, eps=True)
    rcv = d8_receivers(eps, valid, dist)
    acc = accumulation(rcv, order, z.shape)
    n_ref = int(valid.sum()) if n_ref is None else int(n_ref)
    thr = max(1, int(math.ceil(channel_fraction * n_ref)))
    return {"plain": plain, "eps": eps, "rcv": rcv, "acc": acc,
            "threshold": thr, "channel": acc >= thr}


# --------------------------------------------------------------------------
# small helpers on masks
# --------------------------------------------------------------------------

def dilate8(m: np.ndarray) -> np.ndarray:
    """m dilated by one cell in the 8-neighbourhood (3x3 square)."""
    out = m.copy()
    h, w = m.shape
    for dy in (-1, 0, 1):
        for dx in (-1, 0, 1):
            if dy == 0 and dx == 0:
                continue
            ys = slice(max(0, dy), h + min(0, dy))
            yd = slice(max(0, -dy), h + min(0, -dy))
            xs = slice(max(0, dx), w + min(0, dx))
            xd = slice(max(0, -dx), w + min(0, -dx))
            out[yd, xd] |= m[ys, xs]
    return out


def strict_pits(z: np.ndarray, valid: np.ndarray) -> np.ndarray:
    """Cells strictly lower than all 8 neighbours; only cells whose 8
    neighbours are all inside the raster and valid can be pits."""
    h, w = z.shape
    pit = np.zeros(z.shape, dtype=bool)
    if h < 3 or w < 3:
        return pit
    zf = z.astype(np.float64)
    c = zf[1:-1, 1:-1]
    ok = valid[1:-1, 1:-1].copy()
    for k in range(8):
        dy, dx = int(DY[k]), int(DX[k])
        nb = zf[1 + dy:h - 1 + dy, 1 + dx:w - 1 + dx]
        ok &= valid[1 + dy:h - 1 + dy, 1 + dx:w - 1 + dx] & (c < nb)
    pit[1:-1, 1:-1] = ok
    return pit


def f1_scores(chan_fill: np.ndarray, chan_truth: np.ndarray, region: np.ndarray) -> dict:
    """Channel agreement inside ``region`` with a 1-cell (8-neighbourhood)
    tolerance. precision = fill-channel cells in the region within 1 cell of
    a truth-channel cell / fill-channel cells in the region; recall = the
    same the other way; F1 = 2PR/(P+R). None where undefined: no truth
    channel in the region -> recall and F1 None (the case is skipped for F1);
    no fill channel -> precision None, F1 = 0 if the truth has some."""
    fr = chan_fill & region
    tr = chan_truth & region
    nf, nt = int(fr.sum()), int(tr.sum())
    p = float((fr & dilate8(chan_truth)).sum()) / nf if nf else None
    r = float((tr & dilate8(chan_fill)).sum()) / nt if nt else None
    if nt == 0:
        f1 = None
    elif nf == 0 or not p or not r:
        f1 = 0.0
    else:
        f1 = 2 * p * r / (p + r)
    return {"fill_channel_cells": nf, "truth_channel_cells": nt,
            "precision": p, "recall": r, "f1": f1}


# --------------------------------------------------------------------------
# self-check
# --------------------------------------------------------------------------

def _check_drains(name, a, valid, fail):
    """Every valid cell drains to an outlet (no cycles, mass conserved), and
    every non-seed cell of the epsilon surface has a receiver."""
    h, w = valid.shape
    rcv, acc = a["rcv"], a["acc"].ravel()
    outlets = [i for i in range(h * w) if valid.flat[i] and rcv[i] < 0]
    if sum(int(acc[i]) for i in outlets) != int(valid.sum()):
        fail(f"{name}: outlets' accumulations do not sum to the cell count")
    for i in outlets:
        y, x = divmod(i, w)
        border = y in (0, h - 1) or x in (0, w - 1)
        nodata_nb = any(not valid[y + dy, x + dx] for dy, dx in zip(DY, DX)
                        if 0 <= y + dy < h and 0 <= x + dx < w)
        if not (border or nodata_nb):
            fail(f"{name}: interior cell ({y},{x}) has no receiver on the epsilon surface")
    for i in range(h * w):
        if valid.flat[i] and rcv[i] >= 0 and not a["eps"].flat[rcv[i]] < a["eps"].flat[i]:
            fail(f"{name}: cell {i} drains to a cell that is not lower")


def selfcheck(verbose: bool = True) -> bool:
    """Flow routines on tiny hand-made grids with known answers."""
    errors = []
    fail = errors.append

    # 1. V-valley: sides fall 10 m per cell towards column 4, the axis falls
    # 1 m per row towards the bottom edge. No depression; everything drains
    # to the bottom cell of the axis; the axis is the channel.
    h, w = 9, 9
    yy, xx = np.mgrid[0:h, 0:w]
    z = np.abs(xx - 4) * 10.0 + (h - 1 - yy) * 1.0
    valid = np.ones(z.shape, bool)
    a = analyse(z, valid, channel_fraction=5.0 / z.size)   # threshold: 5 cells
    if np.any(a["plain"] != z) or np.any(a["eps"] != z):
        fail("V-valley: filling raised a cell of a surface without depressions")
    if a["acc"][h - 1, 4] != z.size:
        fail(f"V-valley: outlet accumulation {a['acc'][h - 1, 4]} != {z.size}")
    # an axis cell of row y drains rows 0..y (9 cells a row); a side cell at
    # most the 4 cells beside it
    if not np.array_equal(a["acc"][:, 4], (np.arange(h) + 1) * w):
        fail("V-valley: accumulation along the axis is not 9, 18, 27, ...")
    if not np.array_equal(a["channel"], xx == 4):
        fail("V-valley: channel is not the valley axis")
    if strict_pits(z, valid).any():
        fail("V-valley: a strict pit where there is none")
    _check_drains("V-valley", a, valid, fail)

    # 2. a pit: a plane tilted towards the left edge, the centre cell 5 m
    # below its lowest neighbour.
    h, w = 7, 7
    yy, xx = np.mgrid[0:h, 0:w]
    z = xx * 2.0 + yy * 0.1 + 20.0
    z[3, 3] = z[3, 2] - 5.0
    valid = np.ones(z.shape, bool)
    a = analyse(z, valid)
    pits = strict_pits(z, valid)
    if pits.sum() != 1 or not pits[3, 3]:
        fail("pit: strict pit not found exactly at the centre")
    spill = min(z[3 + dy, 3 + dx] for dy, dx in zip(DY, DX))
    if a["plain"][3, 3] != spill:
        fail(f"pit: plain fill level {a['plain'][3, 3]} != spill level {spill}")
    raised = a["plain"] > z
    if raised.sum() != 1:
        fail(f"pit: plain fill raised {raised.sum()} cells, expected 1")
    if not (a["eps"][3, 3] > spill and a["eps"][3, 3] - spill < 1e-9):
        fail("pit: epsilon fill did not lift the pit just above its spill level")
    if np.any(a["eps"][~raised] != z[~raised]):
        fail("pit: epsilon fill changed cells outside the pit")
    _check_drains("pit", a, valid, fail)

    # 3. a flat: every cell equal. Nothing is raised by plain filling; the
    # epsilon surface drains every interior cell to the border.
    z = np.full((6, 8), 100.0)
    valid = np.ones(z.shape, bool)
    a = analyse(z, valid)
    if np.any(a["plain"] != z):
        fail("flat: plain fill raised a flat")
    if strict_pits(z, valid).any():
        fail("flat: strict pit on a flat")
    if not np.all(a["eps"][1:-1, 1:-1] > 100.0) or np.any(a["eps"] - 100.0 > 1e-9):
        fail("flat: epsilon surface is not a tiny gradient above the flat")
    _check_drains("flat", a, valid, fail)

    # 4. a closed basin: a 3x3 floor at 10 m inside a ring at 50 m whose
    # lowest cell (the spill) is 30 m, on a 20 m plain.
    z = np.full((9, 9), 20.0)
    z[2:7, 2:7] = 50.0
    z[3:6, 3:6] = 10.0
    z[2, 4] = 30.0
    valid = np.ones(z.shape, bool)
    a = analyse(z, valid)
    raised = a["plain"] > z
    if raised.sum() != 9 or not raised[3:6, 3:6].all() or np.any(a["plain"][3:6, 3:6] != 30.0):
        fail("basin: plain fill did not make a 9-cell lake at the spill level 30 m")
    _check_drains("basin", a, valid, fail)
    # the basin drains through its spill cell
    if a["acc"][2, 4] < 10:
        fail("basin: the lake does not drain through the spill cell")

    # 5. a nodata sink: a cone falling towards a nodata hole in the middle.
    # Nodata cells are outlets: nothing is raised; cells drain into the hole.
    h, w = 9, 9
    yy, xx = np.mgrid[0:h, 0:w]
    z = np.hypot(yy - 4.0, xx - 4.0) * 3.0
    valid = np.ones(z.shape, bool)
    valid[4, 4] = False
    a = analyse(z, valid)
    if np.any(a["plain"][valid] != z[valid]):
        fail("nodata sink: plain fill raised cells draining into a nodata outlet")
    out = np.argwhere(valid & (a["rcv"].reshape(z.shape) < 0))
    if a["acc"][4, 4] != 0 or len(out) == 0 or np.abs(out - 4).max() > 1:
        fail("nodata sink: cells do not drain into the nodata hole")
    _check_drains("nodata sink", a, valid, fail)

    # 6. F1 with the 1-cell tolerance
    t = np.zeros((10, 10), bool)
    t[:, 5] = True
    reg = np.ones_like(t)
    s = f1_scores(t, t, reg)
    if s["f1"] != 1.0:
        fail("F1: identical channels do not score 1")
    sh1 = np.roll(t, 1, axis=1)
    if f1_scores(sh1, t, reg)["f1"] != 1.0:
        fail("F1: a 1-cell shift is not within the tolerance")
    sh2 = np.roll(t, 2, axis=1)
    if f1_scores(sh2, t, reg)["f1"] != 0.0:
        fail("F1: a 2-cell shift scores above 0")
    if f1_scores(t, np.zeros_like(t), reg)["f1"] is not None:
        fail("F1: defined without a truth channel")
    if f1_scores(np.zeros_like(t), t, reg)["f1"] != 0.0:
        fail("F1: a fill without channels does not score 0")

    if verbose:
        if errors:
            for e in errors:
                print("SELFCHECK FAILED: " + e, flush=True)
        else:
            print("selfcheck: flow routines pass (V-valley, pit, flat, closed basin, "
                  "nodata sink, F1 tolerance)", flush=True)
    return not errors


if __name__ == "__main__":
    import sys
    sys.exit(0 if selfcheck() else 1)
