"""Shared helpers for the mcmd benchmarks (bench/accuracy.py, bench/speed.py).

Everything that both benchmarks need lives here, in one place:

* punching voids into a void-free DEM, deterministically from a seed
  - ``kept3``: keep a random 3.3 % of the cells, the rest becomes nodata
    (the MCMD paper's experiment);
  - ``blobs``: a union of smooth random star-shaped blobs of mixed sizes
    (one large one) covering ~5 % of the area, most of them away from the
    raster border;
* writing the voided GeoTIFF (same data type, CRS, geotransform, nodata;
  a nodata value is declared when the source has none);
* metrics inside the removed cells against the original: RMSE, max abs
  error, Laplacian-spread ratio, mean-slope ratio, completeness;
* running a command under ``/usr/bin/time -v`` (wall time, peak RSS) with a
  timeout;
* hillshade PNGs (gdaldem hillshade) of a window around the largest void;
* ``valleys`` voids (discs centred on given cells, e.g. channel cells) and
  a probe of whether the CLI accepts an option (bench/hydrology.py).

Run with /usr/bin/python3 (needs numpy and osgeo.gdal; nothing else).
"""

from __future__ import annotations

import hashlib
import json
import math
import os
import platform
import re
import signal
import subprocess
import tempfile
import time
from dataclasses import dataclass

import numpy as np
from osgeo import gdal, ogr, osr

gdal.UseExceptions()

BENCH_DIR = os.path.dirname(os.path.abspath(__file__))
ROOT_DIR = os.path.dirname(BENCH_DIR)
# ../shared/dem relative to the project root; MCMD_DEM_DIR overrides it (a
# worktree checked out elsewhere)
DEM_DIR = os.environ.get("MCMD_DEM_DIR") or os.path.normpath(os.path.join(ROOT_DIR, "..", "shared", "dem"))
DEFAULT_MCMD = os.path.join(ROOT_DIR, "build", "bin", "mcmd_fillnodata")
GDAL_FILL = "gdal_fillnodata.py"

KEPT_FRACTION = 0.033
BLOB_COVER = 0.05
PNG_MAX = 256

VOID_KINDS = ("kept3", "blobs", "big")


# --------------------------------------------------------------------------
# raster I/O
# --------------------------------------------------------------------------

@dataclass
class Raster:
    data: np.ndarray          # native dtype, 2-D
    nodata: float | None      # declared nodata (None if the file has none)
    gt: tuple
    wkt: str
    gdal_type: int

    @property
    def shape(self):
        return self.data.shape

    def valid(self) -> np.ndarray:
        return valid_mask(self.data, self.nodata)


def valid_mask(a: np.ndarray, nodata) -> np.ndarray:
    m = np.ones(a.shape, dtype=bool)
    if np.issubdtype(a.dtype, np.floating):
        m &= ~np.isnan(a)
    if nodata is not None and not (isinstance(nodata, float) and math.isnan(nodata)):
        m &= a != np.asarray(nodata).astype(a.dtype)
    return m


def read_raster(path: str, band: int = 1) -> Raster:
    ds = gdal.Open(path)
    b = ds.GetRasterBand(band)
    return Raster(b.ReadAsArray(), b.GetNoDataValue(), ds.GetGeoTransform(),
                  ds.GetProjection(), b.DataType)


def raster_size(path: str) -> tuple[int, int]:
    ds = gdal.Open(path)
    return ds.RasterXSize, ds.RasterYSize


def is_geographic(path: str) -> bool:
    ds = gdal.Open(path)
    wkt = ds.GetProjection()
    if not wkt:
        return False
    srs = osr.SpatialReference()
    srs.ImportFromWkt(wkt)
    return bool(srs.IsGeographic())


def choose_nodata(data: np.ndarray) -> float:
    """A nodata value for a file that declares none, absent from the data."""
    if np.issubdtype(data.dtype, np.floating):
        for v in (-9999.0, -32768.0, -1e30):
            if not np.any(data == v):
                return v
        return float("nan")
    info = np.iinfo(data.dtype)
    for v in (info.min, info.max, 0):
        if not np.any(data == v):
            return float(v)
    raise ValueError("no free value for nodata")


def write_voided(src_path: str, dst_path: str, void: np.ndarray,
                 src: Raster | None = None) -> float:
    """Copy ``src_path`` to ``dst_path`` (GTiff, same type/CRS/geotransform)
    with the cells in ``void`` set to nodata. Returns the nodata value used."""
    src = src or read_raster(src_path)
    nodata = src.nodata if src.nodata is not None else choose_nodata(src.data)
    out = src.data.copy()
    out[void] = np.asarray(nodata).astype(out.dtype)
    h, w = out.shape
    tmp = dst_path + ".part.tif"
    drv = gdal.GetDriverByName("GTiff")
    ds = drv.Create(tmp, w, h, 1, src.gdal_type,
                    options=["TILED=YES", "BLOCKXSIZE=256", "BLOCKYSIZE=256",
                             "COMPRESS=LZW", "BIGTIFF=IF_SAFER"])
    ds.SetGeoTransform(src.gt)
    if src.wkt:
        ds.SetProjection(src.wkt)
    b = ds.GetRasterBand(1)
    b.SetNoDataValue(nodata)
    b.WriteArray(out)
    b = None
    ds = None
    os.replace(tmp, dst_path)
    return nodata


def pixel_size_m(path: str) -> tuple[float, float]:
    """(dx, dy) of a pixel in metres: the geotransform's for a projected CRS;
    for a geographic one, degrees converted at the raster's centre latitude
    (111320 m per degree of latitude, times cos(latitude) for longitude)."""
    ds = gdal.Open(path)
    gt = ds.GetGeoTransform()
    dx, dy = abs(gt[1]), abs(gt[5])
    if is_geographic(path):
        lat = gt[3] + gt[5] * ds.RasterYSize / 2.0
        dy *= 111320.0
        dx *= 111320.0 * math.cos(math.radians(lat))
    return dx, dy


def source_path(src: str, crop, work: str, name: str | None = None) -> str:
    """Path of a DEM of ``DEM_DIR`` (``src``, without .tif), or of its crop
    ``crop`` = (xoff, yoff, w, h) made once under ``work``/inputs as
    ``name``.tif (default: src)."""
    p = os.path.join(DEM_DIR, src + ".tif")
    if crop is None:
        return p
    dst = os.path.join(work, "inputs", (name or src) + ".tif")
    os.makedirs(os.path.dirname(dst), exist_ok=True)
    crop_to(p, dst, *crop)
    return dst


def crop_to(src_path: str, dst_path: str, xoff: int, yoff: int, w: int, h: int):
    """Crop a window of a DEM into a new GTiff (used to add extra void-free
    test DEMs cut out of the big mosaics)."""
    if os.path.exists(dst_path):
        return
    tmp = dst_path + ".part.tif"
    gdal.Translate(tmp, src_path, srcWin=[xoff, yoff, w, h],
                   creationOptions=["TILED=YES", "COMPRESS=LZW"])
    os.replace(tmp, dst_path)


# --------------------------------------------------------------------------
# void punching
# --------------------------------------------------------------------------

def _rng(seed: int, kind: str) -> np.random.Generator:
    # independent streams per void kind, stable across numpy versions
    salt = int.from_bytes(hashlib.sha256(kind.encode()).digest()[:4], "little")
    return np.random.Generator(np.random.PCG64([seed, salt]))


def punch_kept3(shape, seed: int, frac: float = KEPT_FRACTION) -> np.ndarray:
    """Void mask (True = removed) keeping a random ``frac`` of the cells."""
    rng = _rng(seed, "kept3")
    h, w = shape
    void = np.empty(shape, dtype=bool)
    # row chunks keep the temporary small on the 52 M-cell mosaic
    step = max(1, (1 << 22) // max(w, 1))
    for y0 in range(0, h, step):
        y1 = min(h, y0 + step)
        void[y0:y1] = rng.random((y1 - y0, w), dtype=np.float32) >= frac
    return void


def _blob(rng, r: float):
    """A smooth star-shaped blob: radius(theta) = r * (1 + sum a_k cos(k theta + phi_k))."""
    ks = np.arange(2, 7)
    amp = rng.uniform(0.0, 0.35, size=ks.size) / ks ** 0.8
    phase = rng.uniform(0, 2 * np.pi, size=ks.size)
    # anisotropic stretch and rotation
    stretch = rng.uniform(0.6, 1.0)
    rot = rng.uniform(0, np.pi)
    rmax = r * (1 + amp.sum())
    return ks, amp, phase, stretch, rot, rmax


def _raster_blob(void, cx, cy, r, params):
    ks, amp, phase, stretch, rot, rmax = params
    h, w = void.shape
    x0, x1 = max(0, int(cx - rmax) - 1), min(w, int(cx + rmax) + 2)
    y0, y1 = max(0, int(cy - rmax) - 1), min(h, int(cy + rmax) + 2)
    if x0 >= x1 or y0 >= y1:
        return
    yy, xx = np.mgrid[y0:y1, x0:x1].astype(np.float64)
    dx, dy = xx - cx, yy - cy
    c, s = math.cos(rot), math.sin(rot)
    u = c * dx + s * dy
    v = (-s * dx + c * dy) / stretch
    rho = np.hypot(u, v)
    th = np.arctan2(v, u)
    rad = r * (1 + (amp[:, None, None] * np.cos(ks[:, None, None] * th + phase[:, None, None])).sum(0))
    void[y0:y1, x0:x1] |= rho <= rad


def punch_blobs(shape, seed: int, cover: float = BLOB_COVER,
                valid: np.ndarray | None = None) -> np.ndarray:
    """Void mask (True = removed): union of smooth random blobs of mixed sizes
    covering ~``cover`` of the area. One large blob (~1/3 of the cover) sits
    well inside the raster; ~85 % of the others are kept clear of the border,
    the rest are centred near a raster edge (voids touching the border)."""
    rng = _rng(seed, "blobs")
    h, w = shape
    area = float(h * w)
    void = np.zeros(shape, dtype=bool)
    target = cover * area

    # the large one
    r_big = math.sqrt(target / 3.0 / math.pi)
    r_big = min(r_big, 0.3 * min(h, w))
    p = _blob(rng, r_big)
    m = p[5] + 2
    cx = rng.uniform(min(m, w / 2), max(w - m, w / 2))
    cy = rng.uniform(min(m, h / 2), max(h - m, h / 2))
    _raster_blob(void, cx, cy, r_big, p)

    r_min = 1.5
    r_max = max(r_min * 2, r_big / 3.0)
    count = int(void.sum())
    n = 0
    while count < target and n < 100000:
        n += 1
        r = math.exp(rng.uniform(math.log(r_min), math.log(r_max)))
        p = _blob(rng, r)
        if rng.random() < 0.85:
            m = p[5] + 2
            if 2 * m >= min(w, h):
                m = 0
            cx, cy = rng.uniform(m, w - m), rng.uniform(m, h - m)
        else:
            # centred near a random raster edge: a void touching the border
            side = int(rng.integers(4))
            off = rng.uniform(-0.5, 0.5) * r
            if side < 2:
                cx, cy = rng.uniform(0, w), (off if side == 0 else h - 1 + off)
            else:
                cx, cy = (off if side == 2 else w - 1 + off), rng.uniform(0, h)
        # update the count only inside the blob's box
        rmax = p[5]
        x0, x1 = max(0, int(cx - rmax) - 1), min(w, int(cx + rmax) + 2)
        y0, y1 = max(0, int(cy - rmax) - 1), min(h, int(cy + rmax) + 2)
        before = int(void[y0:y1, x0:x1].sum())
        _raster_blob(void, cx, cy, r, p)
        count += int(void[y0:y1, x0:x1].sum()) - before
    if valid is not None:
        void &= valid
    return void


def punch_big(shape, seed: int, valid: np.ndarray | None = None) -> np.ndarray:
    """Void mask (True = removed): one smooth blob (as in punch_blobs) whose
    base radius is an eighth of the raster's width (a void about a quarter
    of the width across), placed at random wholly inside the raster, clear
    of the border by 2 cells where it fits."""
    rng = _rng(seed, "big")
    h, w = shape
    r = w / 8.0
    p = _blob(rng, r)
    m = p[5] + 2
    cx = rng.uniform(min(m, w / 2), max(w - m, w / 2))
    cy = rng.uniform(min(m, h / 2), max(h - m, h / 2))
    void = np.zeros(shape, dtype=bool)
    _raster_blob(void, cx, cy, r, p)
    if valid is not None:
        void &= valid
    return void


def punch(kind: str, shape, seed: int, valid: np.ndarray | None = None) -> np.ndarray:
    if kind == "big":
        return punch_big(shape, seed, valid=valid)
    if kind == "kept3":
        v = punch_kept3(shape, seed)
        if valid is not None:
            v &= valid
        return v
    if kind == "blobs":
        return punch_blobs(shape, seed, valid=valid)
    raise ValueError(f"unknown void kind {kind!r}")


def make_voided(src_path: str, dst_path: str, kind: str, seed: int,
                punch_fn=None, tag: str | None = None) -> dict:
    """Create (once) the voided copy of a void-free DEM. Returns a small info
    dict (also cached next to the file as JSON). ``punch_fn(src Raster) ->
    void mask`` replaces ``punch(kind, ...)`` for kinds that need more than
    the shape (valleys); a cached file is remade when its ``tag`` differs
    (e.g. the channel definition its voids were centred on)."""
    info_path = dst_path + ".json"
    if os.path.exists(dst_path) and os.path.exists(info_path):
        with open(info_path) as f:
            info = json.load(f)
        if info.get("tag") == tag:
            return info
    src = read_raster(src_path)
    valid = src.valid()
    void = punch_fn(src) if punch_fn else punch(kind, src.shape, seed, valid=valid)
    nodata = write_voided(src_path, dst_path, void, src)
    info = {"src": src_path, "kind": kind, "seed": seed,
            "width": src.shape[1], "height": src.shape[0],
            "void_cells": int(void.sum()),
            "void_fraction": float(void.sum()) / void.size,
            "nodata": nodata}
    if tag is not None:
        info["tag"] = tag
    with open(info_path, "w") as f:
        json.dump(info, f, indent=1)
    return info


def punch_valleys(shape, seed: int, centres: np.ndarray, valid: np.ndarray | None = None,
                  n_range=(6, 10), r_range=(8, 25), border: int = 8, gap: int = 2,
                  tries: int = 4000) -> tuple[np.ndarray, list]:
    """Void mask (True = removed) of ``valleys`` voids: n (uniform in
    ``n_range``, inclusive) discs of integer radius r (uniform in
    ``r_range``, inclusive; placed largest first), each centred on a cell of
    ``centres`` (e.g. the true terrain's channel cells) drawn at random.
    A disc is kept only if it stays ``border`` cells clear of the raster
    edge, every cell of it and of a ``gap``-cell ring around it is valid,
    and it is ``gap`` cells clear of the discs already placed (no overlap,
    separate voids). Returns (void, [(cx, cy, r), ...])."""
    rng = _rng(seed, "valleys")
    h, w = shape
    void = np.zeros(shape, dtype=bool)
    ys, xs = np.nonzero(centres)
    n = int(rng.integers(n_range[0], n_range[1] + 1))
    radii = sorted((int(r) for r in rng.integers(r_range[0], r_range[1] + 1, size=n)),
                   reverse=True)
    discs = []
    if ys.size == 0:
        return void, discs
    for r in radii:
        R = r + gap
        yy, xx = np.mgrid[-R:R + 1, -R:R + 1]
        ring = yy * yy + xx * xx <= R * R
        disc = yy * yy + xx * xx <= r * r
        for _ in range(tries):
            i = int(rng.integers(ys.size))
            cy, cx = int(ys[i]), int(xs[i])
            if cx - r < border or cy - r < border or cx + r >= w - border or cy + r >= h - border:
                continue
            if any((cx - x) ** 2 + (cy - y) ** 2 <= (r + q + gap) ** 2 for x, y, q in discs):
                continue
            y0, x0 = cy - R, cx - R
            if y0 < 0 or x0 < 0 or cy + R >= h or cx + R >= w:
                continue
            if valid is not None and not valid[y0:y0 + 2 * R + 1, x0:x0 + 2 * R + 1][ring].all():
                continue
            void[y0:y0 + 2 * R + 1, x0:x0 + 2 * R + 1] |= disc
            discs.append((cx, cy, r))
            break
    return void, discs


# --------------------------------------------------------------------------
# metrics
# --------------------------------------------------------------------------

def _neigh_stats(z: np.ndarray, ys: np.ndarray, xs: np.ndarray):
    """5-point Laplacian and central-difference slope at interior cells
    (ys, xs) of z (float64 gathered values, no full-size temporaries)."""
    c = z[ys, xs]
    n, s = z[ys - 1, xs], z[ys + 1, xs]
    wv, e = z[ys, xs - 1], z[ys, xs + 1]
    lap = n + s + wv + e - 4.0 * c
    slope = np.hypot((e - wv) * 0.5, (s - n) * 0.5)
    return lap, slope


def metrics(truth: np.ndarray, fill: np.ndarray, removed: np.ndarray,
            fill_nodata=None) -> dict:
    """Error metrics over the removed cells.

    rmse, max_err: over removed cells that the fill filled (completeness says
    how many that is). lap_ratio: std of the 5-point Laplacian of the fill
    over removed cells / the same for the truth. slope_ratio: mean gradient
    magnitude (central differences, pixel units) of the fill over removed
    cells / the same for the truth. Both ratios use removed cells whose 4
    neighbours are inside the raster and valid in the fill."""
    ys, xs = np.nonzero(removed)
    n_removed = ys.size
    if n_removed == 0:
        return {"n_removed": 0}
    fvals = fill[ys, xs]
    fvalid = valid_mask(fvals, fill_nodata)
    n_filled = int(fvalid.sum())
    out = {"n_removed": int(n_removed), "n_filled": n_filled,
           "completeness": n_filled / n_removed}
    if n_filled == 0:
        return out
    err = fvals[fvalid].astype(np.float64) - truth[ys[fvalid], xs[fvalid]].astype(np.float64)
    out["rmse"] = float(np.sqrt(np.mean(err * err)))
    out["max_err"] = float(np.max(np.abs(err)))
    out["bias"] = float(np.mean(err))

    h, w = truth.shape
    inner = (ys > 0) & (ys < h - 1) & (xs > 0) & (xs < w - 1)
    ys, xs = ys[inner], xs[inner]
    if ys.size < 2:
        return out
    # fill values as float64 with NaN where the fill left nodata
    ok = np.ones(ys.size, dtype=bool)
    for dy, dx in ((0, 0), (-1, 0), (1, 0), (0, -1), (0, 1)):
        ok &= valid_mask(fill[ys + dy, xs + dx], fill_nodata)
    ys, xs = ys[ok], xs[ok]
    if ys.size < 2:
        return out
    # gather-based: works on the 52 M-cell mosaic without full float copies
    lap_t, sl_t = _neigh_stats(_F64(truth), ys, xs)
    lap_f, sl_f = _neigh_stats(_F64(fill), ys, xs)
    st = float(np.std(lap_t))
    out["lap_fill"] = float(np.std(lap_f))
    out["lap_truth"] = st
    out["lap_ratio"] = out["lap_fill"] / st if st > 0 else float("nan")
    mt = float(np.mean(sl_t))
    out["slope_ratio"] = float(np.mean(sl_f)) / mt if mt > 0 else float("nan")
    return out


class _F64:
    """Index wrapper returning float64 gathers of an array of any dtype."""

    def __init__(self, a):
        self.a = a

    def __getitem__(self, idx):
        return self.a[idx].astype(np.float64)


def completeness(before_nodata: np.ndarray, fill: np.ndarray, fill_nodata) -> dict:
    """For real-void tiles: fraction of the originally-nodata cells the fill filled."""
    ys, xs = np.nonzero(before_nodata)
    n = ys.size
    if n == 0:
        return {"n_removed": 0, "n_filled": 0, "completeness": 1.0}
    nf = int(valid_mask(fill[ys, xs], fill_nodata).sum())
    return {"n_removed": int(n), "n_filled": nf, "completeness": nf / n}


def pixel_md5(path: str) -> str:
    """md5 of the pixel data (band 1..n, native type), ignoring file metadata."""
    ds = gdal.Open(path)
    m = hashlib.md5()
    for i in range(1, ds.RasterCount + 1):
        m.update(np.ascontiguousarray(ds.GetRasterBand(i).ReadAsArray()).tobytes())
    return m.hexdigest()


# --------------------------------------------------------------------------
# timing
# --------------------------------------------------------------------------

_TIME_RE_RSS = re.compile(r"Maximum resident set size \(kbytes\):\s*(\d+)")
_TIME_RE_WALL = re.compile(r"Elapsed \(wall clock\) time \(h:mm:ss or m:ss\):\s*([\d:.]+)")
_TIME_RE_USER = re.compile(r"User time \(seconds\):\s*([\d.]+)")
_TIME_RE_SYS = re.compile(r"System time \(seconds\):\s*([\d.]+)")


def _parse_clock(s: str) -> float:
    parts = [float(p) for p in s.split(":")]
    t = 0.0
    for p in parts:
        t = t * 60 + p
    return t


def parse_time_v(text: str) -> dict:
    out = {}
    m = _TIME_RE_RSS.search(text)
    if m:
        out["rss_mb"] = int(m.group(1)) / 1024.0
    m = _TIME_RE_WALL.search(text)
    if m:
        out["wall_s"] = _parse_clock(m.group(1))
    m = _TIME_RE_USER.search(text)
    if m:
        out["user_s"] = float(m.group(1))
    m = _TIME_RE_SYS.search(text)
    if m:
        out["sys_s"] = float(m.group(1))
    return out


def _limit_as(mb):
    def f():
        import resource
        b = int(mb) * 1024 * 1024
        resource.setrlimit(resource.RLIMIT_AS, (b, b))
    return f


def run_timed(cmd: list[str], timeout: float | None = None, env=None,
              mem_limit_mb: float | None = None) -> dict:
    """Run ``cmd`` under ``/usr/bin/time -v``. Returns rc, wall_s, rss_mb,
    user_s, sys_s, timed_out, stderr tail. On timeout the whole process group
    is killed and ``timed_out`` is True (wall_s is then the timeout).
    ``mem_limit_mb`` caps the address space (RLIMIT_AS) so that a run that
    would need more memory fails instead of pushing the machine into OOM."""
    with tempfile.NamedTemporaryFile("r", suffix=".time", delete=False) as tf:
        tpath = tf.name
    full = ["/usr/bin/time", "-v", "-o", tpath] + [str(c) for c in cmd]
    load1 = os.getloadavg()[0]  # how busy the shared machine was: the times move with it
    t0 = time.monotonic()
    p = subprocess.Popen(full, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                         text=True, start_new_session=True, env=env,
                         preexec_fn=_limit_as(mem_limit_mb) if mem_limit_mb else None)
    timed_out = False
    try:
        so, se = p.communicate(timeout=timeout)
    except subprocess.TimeoutExpired:
        timed_out = True
        try:
            os.killpg(p.pid, signal.SIGKILL)
        except ProcessLookupError:
            pass
        so, se = p.communicate()
    elapsed = time.monotonic() - t0
    try:
        with open(tpath) as f:
            tv = f.read()
    finally:
        os.unlink(tpath)
    res = parse_time_v(tv) if not timed_out else {}
    # /usr/bin/time prints wall time in centiseconds; keep it as a cross-check
    # and report our own monotonic clock (the fork of /usr/bin/time is ~1 ms)
    if "wall_s" in res:
        res["time_v_wall_s"] = res.pop("wall_s")
    res["wall_s"] = elapsed
    res.update({"rc": p.returncode if not timed_out else None, "load1": load1,
                "timed_out": timed_out, "timeout_s": timeout, "mem_limit_mb": mem_limit_mb,
                "cmd": " ".join(str(c) for c in cmd),
                "stderr": (se or "")[-2000:]})
    return res


# --------------------------------------------------------------------------
# fillers
# --------------------------------------------------------------------------

# name -> how to build the command line. mcmd methods need the binary.
MCMD_METHODS = {
    "mcmd": ["-method", "mcmd"],
    "mcmd-rs-auto": ["-method", "mcmd", "-rs", "auto"],
    "paper-ds": ["-method", "paper-ds"],
    "paper-te": ["-method", "paper-te"],
}
GDAL_METHODS = {
    "gdal-si0": ["-si", "0"],
    "gdal-si2": ["-si", "2"],
}


def fill_cmd(method: str, src: str, dst: str, md: int, mcmd: str,
             seed: int | None = None, extra: list[str] | None = None) -> list[str]:
    extra = list(extra or [])
    if method in GDAL_METHODS:
        return [GDAL_FILL, "-q", "-md", str(md)] + GDAL_METHODS[method] + extra + [src, dst]
    if method in MCMD_METHODS:
        args = list(MCMD_METHODS[method])
        if seed is not None and "auto" in args:
            args += ["-seed", str(seed)]
        return [mcmd, "-q"] + args + extra + [src, dst]
    raise ValueError(f"unknown method {method!r}")


def mcmd_status(mcmd: str) -> tuple[bool, str]:
    """(usable, message). Checks that the CLI exists and answers --help."""
    if not os.path.isfile(mcmd) or not os.access(mcmd, os.X_OK):
        return False, (f"mcmd CLI not found at {mcmd!r} (build it, or pass --mcmd PATH); "
                       "mcmd methods are skipped, GDAL still runs")
    try:
        p = subprocess.run([mcmd, "--help"], capture_output=True, text=True, timeout=30)
    except Exception as e:  # noqa: BLE001
        return False, f"mcmd CLI {mcmd!r} does not run: {e}"
    text = (p.stdout or "") + (p.stderr or "")
    return True, text


def mcmd_accepts(mcmd: str, args: list[str], timeout: float = 60) -> tuple[bool, str]:
    """(accepted, message): does the CLI accept ``args``? Fills a 17x17 test
    raster with a 5x5 void with them; a CLI that rejects an option (a mode
    not built yet) fails here, once, instead of on every case."""
    tag = hashlib.md5(f"{os.getpid()} {time.time()} {args}".encode()).hexdigest()[:10]
    d = tempfile.mkdtemp(prefix="mcmd_probe_")
    src, dst = os.path.join(d, f"in_{tag}.tif"), os.path.join(d, f"out_{tag}.tif")
    try:
        yy, xx = np.mgrid[0:17, 0:17]
        z = (100 + 3 * xx + 2 * yy).astype(np.int16)
        z[6:11, 6:11] = -32768
        ds = gdal.GetDriverByName("GTiff").Create(src, 17, 17, 1, gdal.GDT_Int16)
        ds.SetGeoTransform((0, 30, 0, 0, 0, -30))
        b = ds.GetRasterBand(1)
        b.SetNoDataValue(-32768)
        b.WriteArray(z)
        b = ds = None
        try:
            p = subprocess.run([mcmd, "-q"] + list(args) + [src, dst], capture_output=True,
                               text=True, timeout=timeout)
        except Exception as e:  # noqa: BLE001
            return False, f"does not run: {e}"
        if p.returncode != 0 or not os.path.exists(dst):
            tail = ((p.stderr or "") + (p.stdout or "")).strip().splitlines()
            return False, f"rc={p.returncode}: " + (tail[0] if tail else "no output")
        return True, "ok"
    finally:
        for f in (src, dst):
            if os.path.exists(f):
                os.unlink(f)
        os.rmdir(d)


def binary_id(path: str) -> str:
    """Short content hash of a binary, so cached results are redone when it changes."""
    try:
        h = hashlib.sha256()
        with open(path, "rb") as f:
            for chunk in iter(lambda: f.read(1 << 20), b""):
                h.update(chunk)
        return h.hexdigest()[:16]
    except OSError:
        return "missing"


def gdal_id() -> str:
    return "gdal-" + gdal.__version__


# --------------------------------------------------------------------------
# largest void and hillshades
# --------------------------------------------------------------------------

def largest_void_bbox(void: np.ndarray) -> tuple[int, int, int, int] | None:
    """Bounding box (x0, y0, w, h) of the largest 8-connected void component,
    via GDAL's polygonizer (C speed, no scipy)."""
    if not void.any():
        return None
    h, w = void.shape
    mem = gdal.GetDriverByName("MEM").Create("", w, h, 1, gdal.GDT_Byte)
    mem.SetGeoTransform((0, 1, 0, 0, 0, 1))   # pixel coordinates, y down
    b = mem.GetRasterBand(1)
    b.WriteArray(void.astype(np.uint8))
    vds = ogr.GetDriverByName("Memory").CreateDataSource("v")
    lyr = vds.CreateLayer("v", geom_type=ogr.wkbPolygon)
    lyr.CreateField(ogr.FieldDefn("val", ogr.OFTInteger))
    gdal.Polygonize(b, b, lyr, 0, ["8CONNECTED=8"])
    best, best_area = None, -1.0
    for feat in lyr:
        g = feat.GetGeometryRef()
        a = g.GetArea()
        if a > best_area:
            best_area, best = a, g.GetEnvelope()
    if best is None:
        return None
    minx, maxx, miny, maxy = best
    x0, y0 = int(math.floor(minx)), int(math.floor(miny))
    return x0, y0, int(math.ceil(maxx)) - x0, int(math.ceil(maxy)) - y0


def _border_point(void: np.ndarray, bbox, data: np.ndarray | None = None):
    """A void-border cell (a void cell with a valid 4-neighbour) inside
    ``bbox``: with ``data``, the one (of ~500 evenly sampled) whose valid
    surroundings have the most relief (so the detail crop shows terrain, not
    sea); else the one nearest to the bbox centre. None if there is none."""
    x0, y0, bw, bh = bbox
    sub = void[y0:y0 + bh, x0:x0 + bw]
    edge = np.zeros_like(sub)
    edge[1:, :] |= sub[1:, :] & ~sub[:-1, :]
    edge[:-1, :] |= sub[:-1, :] & ~sub[1:, :]
    edge[:, 1:] |= sub[:, 1:] & ~sub[:, :-1]
    edge[:, :-1] |= sub[:, :-1] & ~sub[:, 1:]
    ys, xs = np.nonzero(edge)
    if ys.size == 0:
        return None
    if data is not None and ys.size > 1:
        idx = np.unique(np.linspace(0, ys.size - 1, min(500, ys.size)).astype(int))
        best, best_s = None, -1.0
        H, W = void.shape
        for i in idx:
            y, x = y0 + int(ys[i]), x0 + int(xs[i])
            ya, yb, xa, xb = max(0, y - 48), min(H, y + 49), max(0, x - 48), min(W, x + 49)
            win = data[ya:yb, xa:xb]
            ok = ~void[ya:yb, xa:xb]
            if ok.sum() < 16:
                continue
            sd = float(np.std(win[ok].astype(np.float64)))
            if sd > best_s:
                best_s, best = sd, (x, y)
        if best is not None:
            return float(best[0]), float(best[1])
    d = (xs - bw / 2.0) ** 2 + (ys - bh / 2.0) ** 2
    i = int(np.argmin(d))
    return x0 + float(xs[i]), y0 + float(ys[i])


def void_window(bbox, shape, max_size: int = PNG_MAX, margin: float = 0.25,
                void: np.ndarray | None = None, data: np.ndarray | None = None):
    """A square-ish window around ``bbox`` (x0, y0, w, h) with a margin,
    clipped to the raster. If the window is larger than ``max_size`` it is
    kept whole and the PNG is downsampled (overview); ``detail`` is then a
    full-resolution max_size² window centred on a void border cell (given
    ``void``, the mask; see _border_point), else on the void's centre."""
    H, W = shape
    x0, y0, bw, bh = bbox
    side = int(max(bw, bh) * (1 + 2 * margin)) + 8
    side = max(side, 64)
    cx, cy = x0 + bw / 2.0, y0 + bh / 2.0

    def win(s, cx=cx, cy=cy):
        ww, hh = min(s, W), min(s, H)
        xo = int(round(cx - ww / 2.0))
        yo = int(round(cy - hh / 2.0))
        xo = max(0, min(W - ww, xo))
        yo = max(0, min(H - hh, yo))
        return xo, yo, ww, hh

    main = win(side)
    detail = None
    if max(main[2], main[3]) > max_size:
        bp = _border_point(void, bbox, data) if void is not None else None
        detail = win(max_size, *bp) if bp else win(max_size)
    return main, detail


def hillshade_png(src_path: str, window, out_png: str, max_size: int = PNG_MAX) -> str:
    """gdaldem hillshade of ``window`` (xoff, yoff, w, h) of ``src_path`` as an
    8-bit PNG no larger than max_size². A larger window is averaged down
    first. Nodata (unfilled) cells come out black."""
    xo, yo, w, h = window
    scale = max(w, h) / float(max_size)
    tag = hashlib.md5(f"{src_path}{window}{os.getpid()}{time.time()}".encode()).hexdigest()[:10]
    crop = f"/vsimem/crop_{tag}.tif"
    shade = f"/vsimem/shade_{tag}.tif"
    kw = {"srcWin": [xo, yo, w, h]}
    if scale > 1:
        kw.update(width=max(1, int(round(w / scale))), height=max(1, int(round(h / scale))),
                  resampleAlg="average")
    gdal.Translate(crop, src_path, **kw)
    opts = {"computeEdges": True, "zFactor": 2.0}   # -z 2: more contrast for artefacts
    if is_geographic(src_path):
        opts["scale"] = 111120.0
    gdal.DEMProcessing(shade, crop, "hillshade", **opts)
    os.makedirs(os.path.dirname(os.path.abspath(out_png)), exist_ok=True)
    # small windows are enlarged by an integer factor (nearest) for viewing
    k = int(max_size // max(w, h)) if scale <= 1 else 1
    kw = {"width": w * k, "height": h * k, "resampleAlg": "nearest"} if k >= 2 else {}
    gdal.Translate(out_png, shade, format="PNG", creationOptions=["ZLEVEL=9"], **kw)
    for p in (crop, shade):
        gdal.Unlink(p)
    aux = out_png + ".aux.xml"
    if os.path.exists(aux):
        os.unlink(aux)
    return out_png


# --------------------------------------------------------------------------
# misc
# --------------------------------------------------------------------------

def machine_info() -> str:
    cpu = platform.processor() or ""
    try:
        with open("/proc/cpuinfo") as f:
            for line in f:
                if line.startswith("model name"):
                    cpu = line.split(":", 1)[1].strip()
                    break
    except OSError:
        pass
    mem = ""
    try:
        with open("/proc/meminfo") as f:
            kb = int(f.readline().split()[1])
            mem = f"{kb / 1024 / 1024:.0f} GiB RAM"
    except (OSError, ValueError, IndexError):
        pass
    # The kernel's release is left out: on a VM it names the instance, not the machine.
    return f"{cpu}, {os.cpu_count()} cores, {mem}, {platform.system()}, GDAL {gdal.__version__}"


def git_rev() -> str:
    try:
        r = subprocess.run(["git", "-C", ROOT_DIR, "rev-parse", "--short", "HEAD"],
                           capture_output=True, text=True, timeout=10)
        return r.stdout.strip() or "?"
    except Exception:  # noqa: BLE001
        return "?"


def median(xs):
    xs = [x for x in xs if x is not None and not (isinstance(x, float) and math.isnan(x))]
    if not xs:
        return None
    return float(np.median(xs))


def fmt(x, spec=".3f", none="—"):
    if x is None or (isinstance(x, float) and math.isnan(x)):
        return none
    return format(x, spec)


def load_json(path):
    try:
        with open(path) as f:
            return json.load(f)
    except (OSError, ValueError):
        return None


def save_json(path, obj):
    os.makedirs(os.path.dirname(path), exist_ok=True)
    tmp = path + ".part"
    with open(tmp, "w") as f:
        json.dump(obj, f, indent=1, sort_keys=True)
    os.replace(tmp, path)


# --------------------------------------------------------------------------
# resumable runs
# --------------------------------------------------------------------------

class FillSpec:
    """One fill of a case for cached_fills: where its result is cached, its
    command, its output and how it is scored."""

    def __init__(self, res_path: str, cmd: list[str], out_path: str,
                 timeout: float | None, evaluate):
        self.res_path, self.cmd, self.out_path = res_path, cmd, out_path
        self.timeout, self.evaluate = timeout, evaluate

    def full_key(self, key: str) -> str:
        return key + " | " + " ".join(str(c) for c in self.cmd)


def cached_fills(specs: list[FillSpec], key: str, force: bool = False, log=print,
                 repeat: int = 1, mem_limit_mb: float | None = None) -> list[dict]:
    """The fills of one case, each cached in its ``res_path`` under ``key``
    (binary hash / GDAL version) + its command line, ``evaluate(out_path)``
    merged into its result. When any of them has to run (or with force), all
    of them run, in ``repeat`` interleaved rounds (A B C, A B C, ...), so that
    the times compared (mcmd vs GDAL) come from the same minutes of the same
    machine, not from different runs or from a drift between back-to-back
    repeats of one tool. A fill stops at its first failure; failed and
    timed-out runs are cached too. wall_s and cpu_s (user + system) are the
    medians, rss_mb the maximum, walls all."""
    cached = [load_json(sp.res_path) for sp in specs]
    if not force and all(c and c.get("key") == sp.full_key(key) for c, sp in zip(cached, specs)):
        return cached
    for sp in specs:
        log(f"    run: {' '.join(str(c) for c in sp.cmd)}" + (f"  (x{repeat}, interleaved)" if repeat > 1 else ""))
    tries: list[list[dict]] = [[] for _ in specs]
    for _ in range(max(1, repeat)):
        for sp, t in zip(specs, tries):
            if t and (t[-1]["timed_out"] or t[-1]["rc"] != 0):
                continue  # stopped at its first failure
            if os.path.exists(sp.out_path):
                os.unlink(sp.out_path)
            t.append(run_timed(sp.cmd, timeout=sp.timeout, mem_limit_mb=mem_limit_mb))
    return [_finish(sp, sp.full_key(key), t, log, mem_limit_mb) for sp, t in zip(specs, tries)]


def _finish(sp: FillSpec, full_key: str, tries: list[dict], log, mem_limit_mb) -> dict:
    """Aggregate the tries of one fill (median wall time, max RSS), score the
    output, cache and return the result."""
    r = dict(tries[-1])
    cpu = lambda t: t.get("user_s", 0.0) + t.get("sys_s", 0.0)  # noqa: E731
    r["cpu_s"] = cpu(r)
    if len(tries) > 1 and all(t["rc"] == 0 and not t["timed_out"] for t in tries):
        walls = [t["wall_s"] for t in tries]
        r["walls"] = walls
        r["wall_s"] = float(np.median(walls))
        r["cpu_s"] = float(np.median([cpu(t) for t in tries]))
        r["rss_mb"] = max(t.get("rss_mb", 0) for t in tries)
    r["loads"] = [t["load1"] for t in tries if "load1" in t]
    r["key"] = full_key
    r["ok"] = (not r["timed_out"]) and r["rc"] == 0 and os.path.exists(sp.out_path)
    if r["ok"]:
        try:
            r.update(sp.evaluate(sp.out_path))
        except Exception as e:  # noqa: BLE001
            r["ok"] = False
            r["error"] = f"evaluation failed: {e}"
    elif r["timed_out"]:
        r["error"] = f"timeout > {sp.timeout:.0f} s"
    else:
        tail = (r.get("stderr") or "").strip().splitlines()
        r["error"] = f"rc={r['rc']}: " + (tail[-1] if tail else "no output")
        if mem_limit_mb:
            r["error"] += f" (address-space limit {mem_limit_mb:.0f} MB)"
    r["when"] = time.strftime("%Y-%m-%d %H:%M:%S")
    save_json(sp.res_path, r)
    status = "ok" if r["ok"] else r.get("error", "failed")
    extra = f", rmse {r['rmse']:.3f}" if r.get("rmse") is not None else ""
    log(f"      {status}: {r['wall_s']:.2f} s, {r.get('rss_mb', 0):.0f} MB{extra}")
    return r


def known_unchanged(inp: np.ndarray, valid: np.ndarray, fill: np.ndarray) -> bool:
    """True if every valid input cell is bit-identical in the fill."""
    if inp.shape != fill.shape or inp.dtype != fill.dtype:
        return False
    a, b = inp[valid], fill[valid]
    if np.issubdtype(a.dtype, np.floating):
        a, b = a.view(np.dtype(f"u{a.dtype.itemsize}")), b.view(np.dtype(f"u{b.dtype.itemsize}"))
    return bool(np.array_equal(a, b))


def score_fill(out_path: str, inr: Raster, removed: np.ndarray, truth: np.ndarray | None) -> dict:
    """The metrics of one fill over the removed cells (completeness only
    without a truth), and whether every valid input cell stayed bit-exact."""
    f = read_raster(out_path)
    r = completeness(removed, f.data, f.nodata) if truth is None else metrics(truth, f.data, removed, f.nodata)
    r["known_exact"] = known_unchanged(inr.data, ~removed, f.data)
    return r


def make_work_dirs(work: str):
    """The inputs/, out/ and results/ folders of a benchmark's work folder."""
    for d in ("inputs", "out", "results"):
        os.makedirs(os.path.join(work, d), exist_ok=True)


def run_key(mcmd: str) -> str:
    """The cache key of every result, GDAL's too: a report then always
    compares runs made in the same session with the same binary."""
    return f"mcmd-{binary_id(mcmd)} {gdal_id()}"


def log(*a):
    """Print and flush at once, so progress shows in long benchmark runs."""
    print(*a, flush=True)


def common_parser(doc: str, quick_help: str, only_help: str):
    """The options every benchmark script shares."""
    import argparse
    ap = argparse.ArgumentParser(description=doc.split("\n\n")[0],
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--mcmd", default=DEFAULT_MCMD,
                    help="path to mcmd_fillnodata (default: build/bin/mcmd_fillnodata)")
    ap.add_argument("--quick", action="store_true", help=quick_help)
    ap.add_argument("--only", action="append", default=[], help=only_help)
    ap.add_argument("--mem-limit-mb", type=float, default=8192,
                    help="address-space limit per run (RLIMIT_AS), MB; a run needing more "
                         "fails and is recorded instead of exhausting the shared machine "
                         "(8192; 0 = none)")
    ap.add_argument("--force", action="store_true", help="ignore cached results")
    return ap


def result_cell(r: dict | None, ok_text) -> str:
    """A report table cell: 'not run', the failure, or ok_text(r)."""
    if not r:
        return "not run"
    if not r.get("ok"):
        return r.get("error", "failed").replace("|", "/")[:60]
    return ok_text(r)
