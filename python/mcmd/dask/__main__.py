"""python3 -m mcmd.dask SRC DST: fill a raster file on a Dask cluster.

    python3 -m mcmd.dask SRC DST [--workers N] [--threads-per-worker T]
        [--scheduler ADDRESS] [--chunk CELLS] [-b BAND]... [-md DIST]
        [-rs R|auto] [-seed S] [-method M] [-tile T] [-inner] [-maxvoid N]
        [-o NAME=VALUE]...
        [-co NAME=VALUE]... [-q]

Reads SRC with rioxarray (chunked: each worker reads its blocks), fills every
band (or the -b bands; the others are copied) with mcmd.dask.fill on a
dask.distributed cluster (a LocalCluster of N worker processes by default,
the scheduler at ADDRESS when given), and writes DST as a tiled GeoTIFF, or
as Zarr when DST ends in .zarr. The result is the CLI's, bit for bit
(mcmd_fillnodata SRC DST with the same options). The output is written under
a temporary name beside DST and renamed at the end; Dask's progress bar
shows the chunks computed: a failed or interrupted
run leaves nothing behind. Errors: one line on stderr, exit status 1 (2 for
bad arguments).
"""
from __future__ import annotations

import argparse
import os
import shutil
import sys
import threading
import warnings

from .. import Error

_FLAG_OPTIONS = {"-md": "MAX_DISTANCE", "-rs": "RS", "-seed": "SEED", "-method": "METHOD", "-tile": "TILE_SIZE"}


def parse(argv):
    ap = argparse.ArgumentParser(prog="python3 -m mcmd.dask", description=__doc__.split("\n\n")[0],
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("src")
    ap.add_argument("dst")
    ap.add_argument("--workers", type=int, default=2, help="worker processes of the LocalCluster (default 2)")
    ap.add_argument("--threads-per-worker", type=int, default=1)
    ap.add_argument("--scheduler", help="address of an existing dask.distributed scheduler")
    ap.add_argument("--chunk", type=int, default=1024, help="chunk side in cells (default 1024)")
    ap.add_argument("-b", dest="bands", type=int, action="append", help="band to fill (repeatable)")
    for flag, name in _FLAG_OPTIONS.items():
        ap.add_argument(flag, dest=name, help=f"as mcmd_fillnodata {flag}")
    ap.add_argument("-inner", action="store_true", help="as mcmd_fillnodata -inner")
    ap.add_argument("-maxvoid", help="as mcmd_fillnodata -maxvoid (cells or an area)")
    ap.add_argument("-o", dest="options", action="append", default=[], help="NAME=VALUE library option")
    ap.add_argument("-co", dest="creation", action="append", default=[], help="GeoTIFF creation option")
    ap.add_argument("-q", dest="quiet", action="store_true", help="no progress bar")
    a = ap.parse_args(argv)
    if a.workers < 1 or a.threads_per_worker < 1 or a.chunk < 1:
        ap.error("--workers, --threads-per-worker and --chunk must be >= 1")
    a.fill_options = {}
    for flag, name in _FLAG_OPTIONS.items():
        if getattr(a, name) is not None:
            a.fill_options[name.lower()] = getattr(a, name)
    if a.inner:
        a.fill_options["inner_only"] = True
    if a.maxvoid is not None:
        a.fill_options["max_void"] = a.maxvoid
    for o in a.options:
        if "=" not in o:
            ap.error(f"-o expects NAME=VALUE, got {o!r}")
        name, value = o.split("=", 1)
        a.fill_options[name.strip().lower()] = value
    return a


def main(argv=None) -> int:
    a = parse(argv)
    # rasterio's warning for plain grids, here and in the LocalCluster's workers
    warnings.filterwarnings("ignore", message="Dataset has no geotransform")
    os.environ["PYTHONWARNINGS"] = ",".join(filter(None, [os.environ.get("PYTHONWARNINGS"),
                                                          "ignore:Dataset has no geotransform"]))
    try:
        run(a)
    except (Error, ValueError, OSError, RuntimeError) as e:
        print(f"mcmd.dask: {e}", file=sys.stderr)
        return 1
    except KeyboardInterrupt:
        print("mcmd.dask: interrupted; no output written", file=sys.stderr)
        return 130
    return 0


def run(a) -> None:
    from osgeo import gdal
    gdal.UseExceptions()
    try:
        src = gdal.Open(a.src)
    except RuntimeError as e:
        raise Error(f"cannot open '{a.src}': {e}") from None
    bands = a.bands or [b for b in range(1, src.RasterCount + 1)
                        if src.GetRasterBand(b).GetColorInterpretation() != gdal.GCI_AlphaBand]
    for b in bands:
        if not 1 <= b <= src.RasterCount:
            raise ValueError(f"band {b} does not exist: '{a.src}' has {src.RasterCount} band(s)")
    dst_dir = os.path.dirname(os.path.abspath(a.dst))
    if not os.path.isdir(dst_dir):
        raise Error(f"cannot write '{a.dst}': folder '{dst_dir}' does not exist")
    if os.path.isdir(a.dst) and not a.dst.rstrip("/").endswith(".zarr"):
        raise Error(f"cannot write '{a.dst}': it is a folder")
    check_options(a, src)  # before any cluster starts
    from distributed import Client, LocalCluster
    tmp = os.path.join(dst_dir, f".{os.path.basename(a.dst.rstrip('/'))}.mcmd-tmp-{os.getpid()}")
    cluster = None
    try:
        if a.scheduler:
            client = Client(a.scheduler)
        else:
            cluster = LocalCluster(n_workers=a.workers, threads_per_worker=a.threads_per_worker, processes=True,
                                   dashboard_address=None)
            client = Client(cluster)
        with client:
            filled = fill_bands(a, src, bands)
            if a.dst.rstrip("/").endswith(".zarr"):
                write_zarr(client, filled, tmp, a.quiet)
            else:
                write_geotiff(client, filled, src, bands, tmp, a.creation, a.quiet)
        replace(tmp, a.dst)
    finally:
        remove(tmp)
        if cluster is not None:
            cluster.close()


def check_options(a, src) -> None:
    """A bad option fails here, with the CLI's message. A void cap given as
    an area becomes cells of SRC, as the CLI converts it."""
    from .. import _options
    from .._mcmd import chunk_grid, max_void_cells
    options = _options.fill_options(dict(a.fill_options), caller="mcmd.dask")
    cells = max_void_cells(options, a.src)
    if cells:
        a.fill_options = {k: v for k, v in a.fill_options.items() if k.upper() not in ("MAX_VOID", "MAXVOID")}
        a.fill_options["max_void"] = f"{cells}cells"
        options = _options.fill_options(dict(a.fill_options), caller="mcmd.dask")
    chunk_grid(src.RasterXSize, src.RasterYSize, options)


def fill_bands(a, src, bands):
    """{band: lazy filled DataArray}, read by the workers with rioxarray."""
    import rioxarray
    from . import fill
    data = rioxarray.open_rasterio(a.src, chunks={"band": 1, "y": a.chunk, "x": a.chunk}, lock=False,
                                   mask_and_scale=False)
    filled = {}
    for b in bands:
        band = data.sel(band=b)
        nodata = src.GetRasterBand(b).GetNoDataValue()
        filled[b] = fill(band, nodata=nodata, chunks=a.chunk, **a.fill_options)
    return filled


def write_geotiff(client, filled, src, bands, tmp, creation, quiet) -> None:
    """Chunks are written as they arrive (the client holds one at a time)."""
    from distributed import as_completed, progress
    from osgeo import gdal
    import numpy as np
    W, H, n = src.RasterXSize, src.RasterYSize, src.RasterCount
    options = ["TILED=YES", "BIGTIFF=IF_SAFER"] + list(creation)
    out = gdal.GetDriverByName("GTiff").Create(tmp, W, H, n, src.GetRasterBand(1).DataType, options)
    if src.GetGeoTransform(can_return_null=True) is not None:
        out.SetGeoTransform(src.GetGeoTransform())
    if src.GetProjection():
        out.SetProjection(src.GetProjection())
    out.SetMetadata(src.GetMetadata())
    for b in range(1, n + 1):
        sb, ob = src.GetRasterBand(b), out.GetRasterBand(b)
        if sb.GetNoDataValue() is not None:
            ob.SetNoDataValue(sb.GetNoDataValue())
        ob.SetColorInterpretation(sb.GetColorInterpretation())
        if b not in filled:  # copied as it is, in row strips
            rows = max(1, (1 << 22) // max(W, 1))
            for y in range(0, H, rows):
                ob.WriteArray(sb.ReadAsArray(0, y, W, min(rows, H - y)), 0, y)
    pieces = []
    for b, arr in filled.items():
        data = arr.data
        offsets = [np.cumsum((0,) + c[:-1]) for c in data.chunks]
        for (j, i), block in np.ndenumerate(np.empty(data.numblocks, dtype=object)):
            pieces.append((b, int(offsets[1][i]), int(offsets[0][j]), data.blocks[j, i]))
    futures = client.compute([p[3] for p in pieces])
    where = {f.key: p[:3] for f, p in zip(futures, pieces)}
    failed = []

    def write_all():  # GDAL's dataset stays on this one thread
        try:
            for future in as_completed(futures):
                b, x0, y0 = where[future.key]
                out.GetRasterBand(b).WriteArray(future.result(), x0, y0)
                future.release()
        except BaseException as e:  # noqa: BLE001  (re-raised on the calling thread)
            failed.append(e)

    writer = threading.Thread(target=write_all, name="mcmd.dask writer")
    writer.start()
    if not quiet:
        progress(futures)  # Dask's text progress bar, until every chunk is computed
        print()
    writer.join()
    if failed:
        raise failed[0]
    out.FlushCache()
    out = None


def write_zarr(client, filled, tmp, quiet) -> None:
    import xarray
    from distributed import progress, wait
    ds = xarray.Dataset({f"band_{b}": arr.drop_vars("band", errors="ignore") for b, arr in filled.items()})
    job = ds.to_zarr(tmp, compute=False)
    future = client.compute(job)
    if not quiet:
        progress(future)
        print()
    wait(future)
    future.result()


def replace(tmp: str, dst: str) -> None:
    if os.path.isdir(dst):
        shutil.rmtree(dst)
    os.replace(tmp, dst)


def remove(path: str) -> None:
    if os.path.isdir(path):
        shutil.rmtree(path, ignore_errors=True)
    elif os.path.exists(path):
        os.remove(path)


if __name__ == "__main__":
    sys.exit(main())
