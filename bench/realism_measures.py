"""The realism measures of bench/realism.py: what hydrologists and geomorphologists read off a
DEM, each a number per terrain (cells of dx x dy metres, heights in metres).

* slope: the slope distribution (degrees, Horn's gradient); compared as the Wasserstein-1
  distance between histograms (``slope_distance``);
* hypsometric integral: (mean - min) / (max - min) of the heights;
* spectral exponent: beta of the radially averaged power spectrum P(k) ~ k^-beta, fitted on
  wavelengths from 8 cells to a quarter of the raster (detrended, Hann window);
* drainage density: D8 channel length per area (km / km^2), channels draining at least
  CHANNEL_AREA;
* Hack exponent: h of L ~ A^h, L the longest flow path above a channel cell and A its
  drainage area (fitted on the medians of L in bins of log A);
* bifurcation ratio: Horton's R_b, from the Strahler orders of the channel network
  (N_w / N_w+1 as a log-linear fit over the orders below the highest);
* closed depressions per km^2: connected areas below their spill level (plain Priority-Flood)
  deeper than DEPRESSION_DEPTH;
* lattice energy: the largest departure, over the 2^k lattices (k = 1 .. 5), of the share of
  the Laplacian's energy on the rows and columns that are multiples of 2^k over their share of
  the cells (r or 1/r, whichever is larger). 1 when no subdivision or coarse-to-fine grid
  shows.

Routing is D8 on the epsilon-filled surface (bench/flow.py); the raster border drains.
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit

from flow import DX, DY, pixel_dist, priority_flood, d8_receivers

CHANNEL_AREA = 1.0e6      # m^2: a channel drains at least 1 km^2
DEPRESSION_DEPTH = 1.0    # m: shallower closed depressions are noise, not landforms
SLOPE_BINS = np.linspace(0.0, 90.0, 181)


def slopes(z: np.ndarray, dx: float, dy: float) -> np.ndarray:
    """Horn's slope in degrees of the interior cells."""
    zp = z.astype(np.float64)
    a, b, c = zp[:-2, :-2], zp[:-2, 1:-1], zp[:-2, 2:]
    d, f = zp[1:-1, :-2], zp[1:-1, 2:]
    g, hh, i = zp[2:, :-2], zp[2:, 1:-1], zp[2:, 2:]
    gx = ((c + 2 * f + i) - (a + 2 * d + g)) / (8 * dx)
    gy = ((g + 2 * hh + i) - (a + 2 * b + c)) / (8 * dy)
    return np.degrees(np.arctan(np.hypot(gx, gy))).ravel()


def slope_histogram(z, dx, dy) -> np.ndarray:
    h, _ = np.histogram(slopes(z, dx, dy), bins=SLOPE_BINS)
    return h / max(h.sum(), 1)


def slope_distance(p: np.ndarray, q: np.ndarray) -> float:
    """Wasserstein-1 distance in degrees between two slope histograms."""
    width = SLOPE_BINS[1] - SLOPE_BINS[0]
    return float(np.abs(np.cumsum(p) - np.cumsum(q)).sum() * width)


def hypsometric_integral(z) -> float:
    lo, hi = float(z.min()), float(z.max())
    return (float(z.mean()) - lo) / (hi - lo) if hi > lo else 0.0


def spectral_exponent(z, dx, dy) -> float:
    h, w = z.shape
    yy, xx = np.mgrid[0:h, 0:w]
    a = np.c_[xx.ravel(), yy.ravel(), np.ones(z.size)]
    coef, *_ = np.linalg.lstsq(a, z.ravel().astype(np.float64), rcond=None)
    d = z - (a @ coef).reshape(h, w)
    win = np.outer(np.hanning(h), np.hanning(w))
    p = np.abs(np.fft.fft2(d * win)) ** 2
    ky = np.fft.fftfreq(h, dy)
    kx = np.fft.fftfreq(w, dx)
    k = np.hypot(*np.meshgrid(ky, kx, indexing="ij"))
    cell = max(dx, dy)
    lo, hi = 1.0 / (min(h * dy, w * dx) / 4.0), 1.0 / (8.0 * cell)
    edges = np.logspace(math.log10(lo), math.log10(hi), 25)
    idx = np.digitize(k.ravel(), edges)
    pk = p.ravel()
    xs, ys = [], []
    for b in range(1, len(edges)):
        sel = idx == b
        if sel.sum() >= 4:
            xs.append(math.log10(math.sqrt(edges[b - 1] * edges[b])))
            ys.append(math.log10(pk[sel].mean()))
    slope = np.polyfit(xs, ys, 1)[0]
    return float(-slope)


@njit(cache=True)
def _network(rcv, order, cell_area, step, channel_area, n):
    """Drainage area, longest upstream path and Strahler order of every cell."""
    area = np.full(n, cell_area)
    longest = np.zeros(n)
    for k in range(order.size - 1, -1, -1):
        c = order[k]
        r = rcv[c]
        if r >= 0:
            area[r] += area[c]
            lc = longest[c] + step[c]
            if lc > longest[r]:
                longest[r] = lc
    strahler = np.zeros(n, dtype=np.int64)
    top = np.zeros(n, dtype=np.int64)    # highest order among a cell's channel donors
    count = np.zeros(n, dtype=np.int64)  # donors at that order
    for k in range(order.size - 1, -1, -1):
        c = order[k]
        if area[c] < channel_area:
            continue
        s = 1 if top[c] == 0 else (top[c] + 1 if count[c] >= 2 else top[c])
        strahler[c] = s
        r = rcv[c]
        if r >= 0:
            if s > top[r]:
                top[r] = s
                count[r] = 1
            elif s == top[r]:
                count[r] += 1
    return area, longest, strahler


def _steps(rcv, w, dx, dy):
    """Length in metres from each cell to its receiver (0 at outlets)."""
    n = rcv.size
    i = np.arange(n)
    d = np.zeros(n)
    has = rcv >= 0
    ddx = np.abs((rcv[has] % w) - (i[has] % w)) * dx
    ddy = np.abs((rcv[has] // w) - (i[has] // w)) * dy
    d[has] = np.hypot(ddx, ddy)
    return d


def drainage(z, dx, dy) -> dict:
    """Drainage density, Hack exponent and bifurcation ratio of one DEM."""
    h, w = z.shape
    valid = np.ones(z.shape, dtype=bool)
    eps, order = priority_flood(z, valid, eps=True)
    rcv = d8_receivers(eps, valid, pixel_dist(dx, dy))
    step = _steps(rcv, w, dx, dy)
    area, longest, strahler = _network(rcv, order, dx * dy, step, CHANNEL_AREA, z.size)
    channel = area >= CHANNEL_AREA
    density = step[channel].sum() / 1000.0 / (z.size * dx * dy / 1.0e6)
    # Hack: medians of L in bins of log A.
    la, ll = np.log10(area[channel]), np.log10(np.maximum(longest[channel], 0.5 * dx))
    edges = np.linspace(la.min(), la.max(), 21) if la.size else np.array([0.0, 1.0])
    xs, ys = [], []
    for b in range(len(edges) - 1):
        sel = (la >= edges[b]) & (la < edges[b + 1])
        if sel.sum() >= 10:
            xs.append(np.median(la[sel]))
            ys.append(np.median(ll[sel]))
    hack = float(np.polyfit(xs, ys, 1)[0]) if len(xs) >= 3 else float("nan")
    # Horton: a segment of order w ends where its receiver's order differs.
    ends = channel & ((rcv < 0) | (strahler[np.maximum(rcv, 0)] != strahler))
    orders = strahler[ends]
    top = int(orders.max()) if orders.size else 0
    counts = np.array([int((orders == o).sum()) for o in range(1, top + 1)])
    if top >= 3:
        fit = np.polyfit(np.arange(1, top), np.log10(counts[: top - 1]), 1)[0]
        rb = float(10 ** (-fit))
    else:
        rb = float("nan")
    return {"density": float(density), "hack": hack, "bifurcation": rb}


@njit(cache=True)
def _depressions(raised, depth, min_depth, w, h):
    """Connected (8) areas of raised cells whose deepest cell is at least min_depth."""
    seen = np.zeros(w * h, dtype=np.bool_)
    stack = np.empty(w * h, dtype=np.int64)
    count = 0
    for s in range(w * h):
        if not raised[s] or seen[s]:
            continue
        seen[s] = True
        top = 0
        stack[0] = s
        deepest = 0.0
        while top >= 0:
            c = stack[top]
            top -= 1
            if depth[c] > deepest:
                deepest = depth[c]
            y, x = c // w, c % w
            for k in range(8):
                ny, nx = y + DY[k], x + DX[k]
                if ny < 0 or nx < 0 or ny >= h or nx >= w:
                    continue
                j = ny * w + nx
                if raised[j] and not seen[j]:
                    seen[j] = True
                    top += 1
                    stack[top] = j
        if deepest >= min_depth:
            count += 1
    return count


def depressions_per_km2(z, dx, dy) -> float:
    valid = np.ones(z.shape, dtype=bool)
    plain, _ = priority_flood(z, valid, eps=False)
    depth = (plain - z.astype(np.float64)).ravel()
    n = _depressions(depth > 0, depth, DEPRESSION_DEPTH, z.shape[1], z.shape[0])
    return n / (z.size * dx * dy / 1.0e6)


def lattice_energy(z) -> float:
    zf = z.astype(np.float64)
    lap = np.zeros_like(zf)
    lap[1:-1, 1:-1] = zf[:-2, 1:-1] + zf[2:, 1:-1] + zf[1:-1, :-2] + zf[1:-1, 2:] - 4 * zf[1:-1, 1:-1]
    e = lap * lap
    inner = np.zeros(z.shape, dtype=bool)
    inner[1:-1, 1:-1] = True
    total = e[inner].sum()
    if total <= 0:
        return 1.0
    worst = 0.0
    for k in range(1, 6):
        s = 2 ** k
        lat = np.zeros(z.shape, dtype=bool)
        lat[::s, :] = True
        lat[:, ::s] = True
        lat &= inner
        r = (e[lat].sum() / total) / (lat.sum() / inner.sum())
        worst = max(worst, r, 1.0 / r if r > 0 else math.inf)
    return float(worst)


def measures(z: np.ndarray, dx: float, dy: float) -> dict:
    """Every scalar measure of one DEM, and its slope histogram."""
    z = np.ascontiguousarray(z, dtype=np.float64)
    out = {"hypsometric": hypsometric_integral(z), "spectral": spectral_exponent(z, dx, dy),
           "depressions": depressions_per_km2(z, dx, dy), "lattice": lattice_energy(z)}
    out.update(drainage(z, dx, dy))
    out["slope_hist"] = slope_histogram(z, dx, dy)
    out["mean_slope"] = float(np.degrees(np.arctan(np.tan(np.radians(slopes(z, dx, dy))).mean())))
    return out
