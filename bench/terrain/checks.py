"""What the terrain benchmark measures on a result (the acceptance checks)."""

from __future__ import annotations

import numpy as np


def ridge_maxima(z: np.ndarray, line, on_lines: set) -> tuple[int, int]:
    """Of the line's cells (2 from either end), how many are higher than both cells 1.5 cells
    away across it (direction over +-2 cells; cells on lines skipped): (maxima, profiles)."""
    h, w = z.shape
    maxima = profiles = 0
    for k in range(2, len(line) - 2):
        x, y = line[k]
        dx, dy = line[k + 2][0] - line[k - 2][0], line[k + 2][1] - line[k - 2][1]
        length = np.hypot(dx, dy)
        sides = []
        for s in (1, -1):
            px, py = int(round(x - s * 1.5 * dy / length)), int(round(y + s * 1.5 * dx / length))
            if not (0 <= px < w and 0 <= py < h) or (px, py) in on_lines:
                break
            sides.append(z[py, px])
        if len(sides) < 2:
            continue
        profiles += 1
        maxima += z[y, x] > max(sides)
    return maxima, profiles


def d8_path(z: np.ndarray, start) -> list:
    """Steepest-descent neighbour (drop / distance) from `start` until none or the border."""
    h, w = z.shape
    x, y = start
    path = [start]
    while 0 < x < w - 1 and 0 < y < h - 1 and len(path) < 4 * (w + h):
        best, nxt = 0.0, None
        for dy in (-1, 0, 1):
            for dx in (-1, 0, 1):
                if dx or dy:
                    s = (z[y, x] - z[y + dy, x + dx]) / np.hypot(dx, dy)
                    if s > best:
                        best, nxt = s, (x + dx, y + dy)
        if nxt is None:
            break
        x, y = nxt
        path.append(nxt)
    return path


def river_followed(z: np.ndarray, river) -> tuple[bool, float]:
    """Whether the D8 path from the river's first cell reaches the border, and the share of
    its cells on the river."""
    h, w = z.shape
    path = d8_path(z, river[0])
    on = set(river)
    end = path[-1]
    border = end[0] in (0, w - 1) or end[1] in (0, h - 1)
    return border, sum(p in on for p in path) / len(path)


def sketch_checks(z: np.ndarray, traced) -> dict:
    on_lines = {c for line in traced for c in line}
    m1, p1 = ridge_maxima(z, traced[0], on_lines)
    m2, p2 = ridge_maxima(z, traced[1], on_lines)
    border, share = river_followed(z, traced[2])
    return {"ridge_maxima": (m1 + m2) / max(1, p1 + p2), "river_to_border": border, "river_share": share}


def grid_streaks(z: np.ndarray) -> float:
    """Axis-aligned artefacts: the share of the Laplacian's energy on the rows and columns
    that are multiples of 32 (a subdivision's coarse lattice) over their share of the cells.
    About 1 without artefacts; the paper's diamond-square gives well above."""
    lap = np.zeros_like(z, dtype=np.float64)
    lap[1:-1, 1:-1] = (z[:-2, 1:-1] + z[2:, 1:-1] + z[1:-1, :-2] + z[1:-1, 2:] - 4 * z[1:-1, 1:-1])
    e = lap * lap
    lattice = np.zeros(z.shape, dtype=bool)
    lattice[::32, :] = True
    lattice[:, ::32] = True
    lattice[0, :] = lattice[-1, :] = lattice[:, 0] = lattice[:, -1] = False
    inner = np.zeros(z.shape, dtype=bool)
    inner[1:-1, 1:-1] = True
    total = e[inner].sum()
    return float((e[lattice & inner].sum() / total) / ((lattice & inner).sum() / inner.sum())) if total > 0 else 1.0
