"""The inputs of the terrain benchmark, drawn with numpy (and PIL for text).

Every function returns arrays; terrain_bench.py writes them as images.
Grey sketches are UInt16 (65535 = unknown) or Byte (255 = unknown), as a
terrain artist would save them from an image editor.
"""

from __future__ import annotations

import math

import numpy as np

WHITE16 = 65535


def polyline(points):
    """The 8-connected cells of a polyline through (x, y) points, in order, each once."""
    cells = []
    for (x0, y0), (x1, y1) in zip(points[:-1], points[1:]):
        steps = int(math.ceil(max(abs(x1 - x0), abs(y1 - y0))))
        for s in range(steps + 1):
            t = s / steps if steps else 0.0
            c = (int(round(x0 + t * (x1 - x0))), int(round(y0 + t * (y1 - y0))))
            if not cells or cells[-1] != c:
                cells.append(c)
    return cells


def ridges_and_river(n: int):
    """Two ridge lines and a river descending to the right border (the acceptance sketch).

    Returns (grey UInt16 levels = 10 x elevation, RGB states: red ridges, blue river,
    [ridge cells, ridge cells, river cells])."""
    s = (n - 1) / 512.0
    lines = [([(60, 100), (200, 150), (330, 120), (460, 170)], 880, 940, 0),
             ([(70, 420), (220, 360), (350, 390), (470, 330)], 840, 920, 0),
             ([(120, 255), (250, 265), (380, 245), (512, 255)], 480, 80, 2)]
    grey = np.full((n, n), WHITE16, np.uint16)
    rgb = np.zeros((3, n, n), np.uint8)
    traced = []
    for points, z0, z1, band in lines:
        cells = polyline([(x * s, y * s) for x, y in points])
        for k, (x, y) in enumerate(cells):
            grey[y, x] = round(10 * (z0 + (z1 - z0) * k / (len(cells) - 1)))
            rgb[band, y, x] = 255
        traced.append(cells)
    return grey, rgb, traced


def five_points(n: int, corner: float = 500.0, centre: float = 1000.0):
    """The paper's Fig. 2 constraints as -point arguments."""
    m = n - 1
    pts = [(0, 0, corner), (m, 0, corner), (0, m, corner), (m, m, corner), (m // 2, m // 2, centre)]
    args = []
    for c, r, z in pts:
        args += ["-point", str(c), str(r), repr(z)]
    return args


def circle_and_segments(n: int):
    """Fig. 5/8: a centred circle at the top elevation, four diagonal segments at a medium
    one, the bottom-left segment shifted a cell to the left. Byte grey, 255 unknown."""
    img = np.full((n, n), 255, np.uint8)
    c, r = (n - 1) / 2, (n - 1) * 0.22
    steps = int(2 * math.pi * r * 2)  # half-cell steps: a closed 8-connected ring
    for k in range(steps):
        a = 2 * math.pi * k / steps
        img[int(round(c + r * math.sin(a))), int(round(c + r * math.cos(a)))] = 230
    inner, outer = r + 8, (n - 1) * 0.47
    for dx, dy, shift in ((1, 1, 0), (-1, 1, -1), (1, -1, 0), (-1, -1, 0)):
        for t in np.arange(inner, outer, 0.5):
            x = int(round(c + dx * t / math.sqrt(2))) + shift
            y = int(round(c + dy * t / math.sqrt(2)))
            img[y, x] = 120
    return img


# A rough outline of Africa (longitude, latitude).
AFRICA = [(-17, 21), (-16, 28), (-10, 30), (-6, 36), (10, 37), (11, 33), (20, 31), (25, 32), (32, 31),
          (34, 28), (38, 18), (43, 12), (51, 12), (48, 5), (41, -2), (40, -10), (35, -24), (32, -29),
          (27, -34), (20, -35), (18, -29), (14, -22), (12, -13), (13, -6), (9, -1), (9, 4), (5, 5),
          (-4, 5), (-8, 4), (-13, 8), (-17, 14), (-17, 21)]


def _draw(n: int):
    from PIL import Image, ImageDraw
    img = Image.new("L", (n, n), 255)
    return img, ImageDraw.Draw(img)


def _font(size: int):
    from PIL import ImageFont
    for name in ("/usr/share/fonts/truetype/dejavu/DejaVuSans-Bold.ttf",
                 "/usr/share/fonts/truetype/lato/Lato-Bold.ttf"):
        try:
            return ImageFont.truetype(name, size)
        except OSError:
            continue
    return ImageFont.load_default()


def africa_sketch(n: int):
    """Fig. 12: the Africa silhouette (filled, grey 200) and the text "Afrigraph '07" (grey 70)
    in a grey image, white unknown, its border at 10 (a sea level for the silhouette to rise from)."""
    img, draw = _draw(n)
    draw.rectangle([0, 0, n - 1, n - 1], outline=10, width=2)
    pts = [((lon + 20) / 75 * 0.55 * n + 0.08 * n, (38 - lat) / 75 * 0.55 * n + 0.06 * n) for lon, lat in AFRICA]
    draw.polygon(pts, fill=200)
    draw.text((0.12 * n, 0.76 * n), "Afrigraph '07", fill=70, font=_font(n // 9))
    return np.array(img, dtype=np.uint8)


def material_sketch(n: int, seed: int = 13):
    """Fig. 13: 1 % of random grey pixels ("salt and pepper"), the silhouette and the text."""
    a = africa_sketch(n)
    rng = np.random.default_rng(seed)
    noise = rng.random((n, n)) < 0.01
    a[noise & (a == 255)] = rng.integers(0, 255, int((noise & (a == 255)).sum()))
    return a


def lsystem_sketch(n: int, depth: int = 7):
    """Fig. 11(b): the bracketed L-system of the paper's footnote drawn as constraints.

    theta0 = pi/2, theta = pi/25, axiom +++++++X, X -> F[@.5++++++X]-F[@.4-----!X]@.6X,
    with @s scaling the step, ! swapping the turn directions, [ ] a branch. The path is
    high at the trunk and lower along the branches (Byte grey, 255 unknown)."""
    rule = "F[@.5++++++X]-F[@.4-----!X]@.6X"
    word = "+++++++X"
    for _ in range(depth):
        word = "".join(rule if ch == "X" else ch for ch in word)
    x, y, a, step, sign, z = 0.0, 0.0, math.pi / 2, 1.0, 1, 1.0
    stack, segments = [], []
    i = 0
    while i < len(word):
        ch = word[i]
        if ch == "F":
            nx, ny = x + step * math.cos(a), y - step * math.sin(a)
            segments.append((x, y, nx, ny, z))
            x, y = nx, ny
            z *= 0.93
        elif ch in "+-":
            a += (1 if ch == "+" else -1) * sign * math.pi / 25
        elif ch == "!":
            sign = -sign
        elif ch == "@":
            j = i + 1
            while j < len(word) and (word[j] == "." or word[j].isdigit()):
                j += 1
            step *= float(word[i + 1:j])
            i = j - 1
        elif ch == "[":
            stack.append((x, y, a, step, sign, z))
        elif ch == "]":
            x, y, a, step, sign, z = stack.pop()
        i += 1
    # The drawing scaled into the raster with a margin.
    xs = [p for s in segments for p in (s[0], s[2])]
    ys = [p for s in segments for p in (s[1], s[3])]
    scale = 0.9 * n / max(max(xs) - min(xs), max(ys) - min(ys))
    ox = (n - scale * (max(xs) - min(xs))) / 2 - scale * min(xs)
    oy = (n - scale * (max(ys) - min(ys))) / 2 - scale * min(ys)
    img, draw = _draw(n)
    for x0, y0, x1, y1, z in segments:
        draw.line([(ox + scale * x0, oy + scale * y0), (ox + scale * x1, oy + scale * y1)],
                  fill=int(40 + 150 * (1 - z)), width=1)
    return np.array(img, dtype=np.uint8)
