#!/usr/bin/python3
"""The peers of the accuracy benchmark: GRASS r.fillnulls and SAGA's Close Gaps
tools, each driven non-interactively on one voided GeoTIFF.

    /usr/bin/python3 bench/peers.py TOOL SRC DST

TOOL is one of PEERS (below). DST gets the fill on SRC's exact grid, in SRC's
data type (integers rounded), with SRC's georeferencing and nodata; the run
fails (exit 1, one line) when the tool fails or writes anything else than
SRC's grid. The whole run is what bench/accuracy.py times: the tool's own
start-up (a GRASS session, saga_cmd) and this wrapper's (~0.2 s) included.

GRASS gets the raster's own grid with its cells' size in metres: a
geographic raster is copied with the geotransform of a local metric grid
(the same cells, no resampling; cell size from voids.pixel_size_m) and no
CRS, a projected one keeps its cell size. Distances are then isotropic, as
in a projected CRS, which is how a GIS user would run a spline. It also
works around a bug of GRASS 8.2.1: r.fillnulls method=rst grows each hole's
region by "%d" % (edge * 2 * resolution), which is 0 for cells a fraction
of a degree wide, and g.region rejects `n=n+0` ("Invalid input <n=n+0>"):
RST fails on every geographic raster. SAGA gets the raster as it is: its
grids have square cells, and a geographic raster's cells, square in degrees,
are not in metres (SAGA would resample them onto another grid).
"""

from __future__ import annotations

import os
import shutil
import subprocess
import sys
import tempfile

import numpy as np
from osgeo import gdal

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import voids as V  # noqa: E402

gdal.UseExceptions()

# Bump when what a peer computes changes (its cached results are then redone).
DRIVER_VERSION = 2

# name -> (tool, arguments). GRASS: r.fillnulls' method, every other option at
# its default (rst: tension 40, smooth 0.1, edge 3, npmin 600, segmax 300;
# bicubic/bilinear: r.resamp.bspline with steps of 3 cells, lambda 0.01).
# SAGA: the grid_tools tool id and its options at their defaults.
PEERS = {
    "grass-rst": ("grass", "rst"),
    "grass-rst-stock": ("grass", "rst"),     # r.fillnulls itself: validates grass-rst
    "grass-bicubic": ("grass", "bicubic"),
    "grass-bilinear": ("grass", "bilinear"),
    "saga-gaps": ("saga", ["7"]),            # Close Gaps (tension threshold 0.1)
    "saga-spline": ("saga", ["25"]),         # Close Gaps with Spline
    "saga-stepwise": ("saga", ["29"]),       # Close Gaps with Stepwise Resampling (B-spline, grow 2)
}
LABEL = {
    "grass-rst": "GRASS r.fillnulls rst", "grass-bicubic": "GRASS r.fillnulls bicubic",
    "grass-bilinear": "GRASS r.fillnulls bilinear", "saga-gaps": "SAGA Close Gaps",
    "saga-spline": "SAGA Close Gaps with Spline", "saga-stepwise": "SAGA Close Gaps Stepwise",
}
# The field of each SAGA tool's input and output grids.
SAGA_IO = {"7": ("-INPUT", "-RESULT"), "25": ("-GRID", "-CLOSED"), "29": ("-INPUT", "-RESULT")}


def peer_key() -> str:
    """The cache key of the peers' results: the tools' versions and
    DRIVER_VERSION."""
    versions = []
    for cmd in (["grass", "--version"], ["saga_cmd", "--version"]):
        try:
            p = subprocess.run(cmd, capture_output=True, text=True, timeout=60)
            text = (p.stdout or "") + (p.stderr or "")
            versions.append(next((ln.strip() for ln in text.splitlines() if any(c.isdigit() for c in ln)),
                                 "?"))
        except (OSError, subprocess.SubprocessError):
            versions.append("missing")
    return f"peers-v{DRIVER_VERSION} {' '.join(versions)} {V.gdal_id()}"


class PeerError(Exception):
    pass


def available(tool: str) -> tuple[bool, str]:
    """(usable, message) for 'grass' or 'saga'."""
    exe = {"grass": "grass", "saga": "saga_cmd"}[tool]
    if shutil.which(exe):
        return True, "ok"
    return False, (f"{exe} not found (bench/install_peers.sh installs Debian's "
                   f"{'grass-core' if tool == 'grass' else 'saga'})")


def metric_copy(src: str, dst: str) -> tuple:
    """SRC as a GeoTIFF on a metric grid (see the module's docstring); returns
    the geotransform written."""
    ds = gdal.Open(src)
    dx, dy = V.pixel_size_m(src) if V.is_geographic(src) else (abs(ds.GetGeoTransform()[1]),
                                                                abs(ds.GetGeoTransform()[5]))
    w, h = ds.RasterXSize, ds.RasterYSize
    gt = (0.0, dx, 0.0, h * dy, 0.0, -dy)
    b = ds.GetRasterBand(1)
    out = gdal.GetDriverByName("GTiff").Create(dst, w, h, 1, b.DataType)
    out.SetGeoTransform(gt)
    ob = out.GetRasterBand(1)
    nodata = b.GetNoDataValue()
    data = b.ReadAsArray()
    if nodata is None:
        raise PeerError("the input declares no nodata value")
    ob.SetNoDataValue(nodata)
    ob.WriteArray(data)
    ob = out = None
    return gt


def same_grid(path: str, w: int, h: int, gt: tuple) -> str | None:
    """None if PATH is w×h with geotransform gt (to 1e-6 of a cell), else why not."""
    ds = gdal.Open(path)
    if (ds.RasterXSize, ds.RasterYSize) != (w, h):
        return f"{ds.RasterXSize}x{ds.RasterYSize} cells, the input has {w}x{h}"
    g = ds.GetGeoTransform()
    cell = max(abs(gt[1]), abs(gt[5]))
    if any(abs(a - b) > 1e-6 * cell for a, b in zip(g, gt)):
        return f"geotransform {g}, the input's is {gt}"
    return None


def run(cmd: list[str], cwd: str, env=None) -> None:
    p = subprocess.run(cmd, cwd=cwd, capture_output=True, text=True, env=env)
    text = (p.stderr or "") + (p.stdout or "")
    errors = [ln for ln in text.splitlines() if ln.startswith("ERROR")]
    if p.returncode != 0 or errors:
        tail = errors or text.strip().splitlines()[-3:] or ["no output"]
        raise PeerError(f"{cmd[0]} failed (rc={p.returncode}): " + " / ".join(tail))


def grass_fill(method: str, src: str, out: str, tmp: str) -> None:
    """r.fillnulls method=METHOD on SRC in a temporary XY location; OUT gets
    the filled raster as Float64 GeoTIFF."""
    script = os.path.join(tmp, "fill.sh")
    with open(script, "w") as f:
        f.write("set -e\n"
                f"r.in.gdal -o input='{src}' output=dem --quiet\n"
                "g.region raster=dem\n"
                f"r.fillnulls input=dem output=filled method={method} --quiet\n"
                f"r.out.gdal -c input=filled output='{out}' format=GTiff type=Float64 "
                "nodata=-1e300 --quiet\n")
    env = dict(os.environ, GRASS_VERBOSE="0")
    run(["grass", "--tmp-location", "XY", "--exec", "sh", script], cwd=tmp, env=env)


# r.fillnulls method=rst's defaults (GRASS 8.2.1).
RST_EDGE, RST_TENSION, RST_SMOOTH, RST_SEGMAX, RST_NPMIN = 3, 40.0, 0.1, 300, 600


def grow_disk(ew: float, ns: float) -> np.ndarray:
    """r.grow's neighbourhood of radius edge + 0.01 (Euclidean): cells whose
    centre lies within that many cells of the mean size sqrt(ew·ns)."""
    r = RST_EDGE + 1
    yy, xx = np.mgrid[-r:r + 1, -r:r + 1]
    return (xx * xx * (ew / ns) + yy * yy * (ns / ew)) <= (RST_EDGE + 0.01) ** 2


def rst_holes(valid: np.ndarray, disk: np.ndarray) -> np.ndarray:
    """r.fillnulls' holes: the void cells grown by `disk` (r.grow), clumped
    with 4-neighbours (r.clump), the labels kept on the void cells: voids
    closer than ~2 edges are one hole. 0 = not void."""
    from scipy import ndimage as ndi
    grown = ndi.binary_dilation(~valid, structure=disk)
    labels, _ = ndi.label(grown)
    labels[valid] = 0
    return labels


def grass_rst_inside(src: str, out: str, tmp: str) -> None:
    """Inside a GRASS session: what r.fillnulls method=rst does, hole by hole,
    with its defaults, without the per-hole map algebra and vector
    bookkeeping: each hole's region is its bounding box grown by 2 edges, its
    points the known cells within edge + 0.01 cells of it (cell centres),
    interpolated by v.surf.rst with r.fillnulls' tension, smoothing, segmax
    and npmin (npmin = the points, segmax = twice them, for fewer than segmax
    points). The hole's cells take v.surf.rst's values."""
    import grass.script as gs
    from grass.script import array as garray
    from scipy import ndimage as ndi
    inr = V.read_raster(src)
    valid = inr.valid()
    h, w = valid.shape
    gt = inr.gt
    ew, ns = gt[1], -gt[5]
    west, north = gt[0], gt[3]
    z = inr.data.astype(np.float64)
    out_z = np.where(valid, z, np.nan)
    disk = grow_disk(ew, ns)
    labels = rst_holes(valid, disk)
    pts = os.path.join(tmp, "pts.txt")
    env = dict(os.environ, GRASS_VERBOSE="0")
    for k, sl in enumerate(ndi.find_objects(labels), start=1):
        if sl is None:
            continue
        m = 2 * RST_EDGE
        r0, r1 = sl[0].start - m, sl[0].stop + m   # the region, in rows and columns
        c0, c1 = sl[1].start - m, sl[1].stop + m
        a0, a1, b0, b1 = max(0, r0), min(h, r1), max(0, c0), min(w, c1)
        hole = labels[a0:a1, b0:b1] == k
        near = ndi.binary_dilation(hole, structure=disk) & valid[a0:a1, b0:b1]
        ys, xs = np.nonzero(near)
        if ys.size < 2:
            continue   # r.fillnulls: "No points to interpolate", the hole stays empty
        with open(pts, "w") as f:
            for y, x in zip(ys, xs):
                f.write(f"{west + (b0 + x + 0.5) * ew!r}|{north - (a0 + y + 0.5) * ns!r}|"
                        f"{z[a0 + y, b0 + x]!r}\n")
        npmin, segmax = (ys.size, 2 * ys.size) if ys.size < RST_SEGMAX else (RST_NPMIN, RST_SEGMAX)
        gs.run_command("g.region", n=north - r0 * ns, s=north - r1 * ns, w=west + c0 * ew,
                       e=west + c1 * ew, nsres=ns, ewres=ew, env=env)
        gs.run_command("v.in.ascii", flags="zt", input=pts, output="hole", format="point",
                       separator="pipe", x=1, y=2, z=3, overwrite=True, env=env)
        gs.run_command("v.surf.rst", input="hole", elevation="hole_dem", tension=RST_TENSION,
                       smooth=RST_SMOOTH, segmax=segmax, npmin=npmin, overwrite=True, env=env)
        vals = np.asarray(garray.array("hole_dem", null=np.nan), dtype=np.float64)
        sub = vals[a0 - r0:a0 - r0 + (a1 - a0), b0 - c0:b0 - c0 + (b1 - b0)]
        tgt = out_z[a0:a1, b0:b1]
        tgt[hole] = sub[hole]
    nodata = -1e300
    ds = gdal.GetDriverByName("GTiff").Create(out, w, h, 1, gdal.GDT_Float64)
    ds.SetGeoTransform(gt)
    b = ds.GetRasterBand(1)
    b.SetNoDataValue(nodata)
    b.WriteArray(np.where(np.isnan(out_z), nodata, out_z))
    b = ds = None


def grass_rst(src: str, out: str, tmp: str) -> None:
    env = dict(os.environ, GRASS_VERBOSE="0")
    run(["grass", "--tmp-location", "XY", "--exec", sys.executable, os.path.abspath(__file__),
         "--inside-grass-rst", src, out, tmp], cwd=tmp, env=env)


def saga_fill(args: list[str], src: str, out: str, tmp: str) -> None:
    tool = args[0]
    i, o = SAGA_IO[tool]
    run(["saga_cmd", "-f=q", "grid_tools"] + args + [i, src, o, out], cwd=tmp)


def fill(peer: str, src: str, dst: str) -> None:
    tool, arg = PEERS[peer]
    ok, msg = available(tool)
    if not ok:
        raise PeerError(msg)
    inr = V.read_raster(src)
    h, w = inr.shape
    tmp = tempfile.mkdtemp(prefix="mcmd_peer_", dir=os.path.dirname(os.path.abspath(dst)))
    try:
        if tool == "grass":
            work = os.path.join(tmp, "in.tif")
            gt = metric_copy(src, work)
        else:   # SAGA grids have square cells: the raster as it is (see the docstring)
            work, gt = os.path.abspath(src), inr.gt
        out = os.path.join(tmp, "out.tif")
        if peer == "grass-rst":
            grass_rst(work, out, tmp)
        elif peer == "grass-rst-stock":
            grass_fill("rst", work, out, tmp)
        elif tool == "grass":
            grass_fill(arg, work, out, tmp)
        else:
            saga_fill(arg, work, out, tmp)
        if not os.path.exists(out):
            raise PeerError(f"{peer} wrote no output")
        bad = same_grid(out, w, h, gt)
        if bad:
            raise PeerError(f"{peer}'s output is not on the input's grid: {bad}")
        f = V.read_raster(out)
        write_like(src, inr, f, dst)
    finally:
        shutil.rmtree(tmp, ignore_errors=True)


def write_like(src: str, inr: V.Raster, f: V.Raster, dst: str) -> None:
    """The fill F, every cell of it (known cells too: the score checks that
    they are unchanged), as a GeoTIFF with SRC's georeferencing, data type and
    nodata; cells F leaves empty are nodata, integers are rounded and clamped."""
    filled = f.valid()
    vals = f.data.astype(np.float64)
    nodata = inr.nodata
    out = np.full(inr.shape, nodata, dtype=inr.data.dtype)
    if np.issubdtype(out.dtype, np.integer):
        info = np.iinfo(out.dtype)
        v = np.clip(np.rint(vals), info.min, info.max)
        if nodata is not None:   # never the nodata value by accident
            v[v == nodata] = nodata + (1 if nodata < info.max else -1)
        vals = v
    out[filled] = vals[filled].astype(out.dtype)
    tmp = dst + ".part.tif"
    ds = gdal.GetDriverByName("GTiff").Create(tmp, out.shape[1], out.shape[0], 1, inr.gdal_type,
                                              options=["COMPRESS=LZW", "TILED=YES"])
    ds.SetGeoTransform(inr.gt)
    if inr.wkt:
        ds.SetProjection(inr.wkt)
    b = ds.GetRasterBand(1)
    if nodata is not None:
        b.SetNoDataValue(nodata)
    b.WriteArray(out)
    b = ds = None
    os.replace(tmp, dst)


def main(argv=None) -> int:
    argv = sys.argv[1:] if argv is None else argv
    if argv and argv[0] == "--inside-grass-rst":
        grass_rst_inside(*argv[1:])
        return 0
    if len(argv) != 3 or argv[0] not in PEERS:
        print("usage: peers.py {" + ",".join(PEERS) + "} SRC DST", file=sys.stderr)
        return 2
    try:
        fill(*argv)
    except (PeerError, RuntimeError, OSError) as e:
        print(f"ERROR: {e}", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
