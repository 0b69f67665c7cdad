"""python3 -m mcmd.dask SRC DST: fill a raster file with Dask.

    python3 -m mcmd.dask SRC DST [--threads N | --workers N | --scheduler ADDRESS]
        [--threads-per-worker T] [--chunk CELLS] [-b BAND]... [-md DIST]
        [-rs R|auto] [-seed S] [-method M] [-tile T] [-inner] [-maxvoid N]
        [-o NAME=VALUE]... [-co NAME=VALUE]... [-q]

Fills every band (or the -b bands; the others are copied) of SRC and writes
DST as a tiled GeoTIFF, or as Zarr when DST ends in .zarr: the result is
mcmd_fillnodata's, bit for bit, with the same options. By default the graph
runs on Dask's threaded scheduler in this process; --workers N starts a
LocalCluster of N worker processes, --scheduler ADDRESS uses a running
dask.distributed scheduler (every worker must read SRC at the same path).
Each task reads its own window of SRC; the filled chunks are written as they
arrive, under a temporary name beside DST renamed at the end: a failed or
interrupted run leaves nothing behind. Errors: one line on stderr, exit
status 1 (2 for bad arguments, 130 when interrupted).
"""
from __future__ import annotations

import argparse
import os
import shutil
import sys
import threading
import uuid

_FLAG_OPTIONS = {"-md": "MAX_DISTANCE", "-rs": "RS", "-seed": "SEED", "-method": "METHOD", "-tile": "TILE_SIZE"}
_FLAGS_OF = {"FILL_FROM": "-fill-from", "FILL_FROM_RESAMPLING": "-fill-from", "RIVERS": "-rivers",
             "RIDGES": "-ridges", "MORPH": "-morph auto"}


class Failure(Exception):
    """A failure reported as the command's one line."""


def parse(argv):
    ap = argparse.ArgumentParser(prog="python3 -m mcmd.dask", description=__doc__.split("\n\n")[2],
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("src")
    ap.add_argument("dst")
    where = ap.add_mutually_exclusive_group()
    where.add_argument("--threads", type=int, help="threads of the threaded scheduler (default: every CPU)")
    where.add_argument("--workers", type=int, help="start a LocalCluster of this many worker processes")
    where.add_argument("--scheduler", help="address of a running dask.distributed scheduler")
    ap.add_argument("--threads-per-worker", type=int, default=1, help="threads of each LocalCluster worker (1)")
    ap.add_argument("--chunk", type=int, default=2048, help="chunk side in cells (default 2048)")
    ap.add_argument("-b", dest="bands", type=int, action="append", help="band to fill (repeatable)")
    for flag, name in _FLAG_OPTIONS.items():
        ap.add_argument(flag, dest=name, help=f"as mcmd_fillnodata {flag}")
    ap.add_argument("-inner", action="store_true", help="as mcmd_fillnodata -inner")
    ap.add_argument("-maxvoid", help="as mcmd_fillnodata -maxvoid (cells or an area)")
    ap.add_argument("-o", dest="options", action="append", default=[], help="NAME=VALUE library option")
    ap.add_argument("-co", dest="creation", action="append", default=[], help="GeoTIFF creation option")
    ap.add_argument("-q", dest="quiet", action="store_true", help="no progress bar")
    a = ap.parse_args(argv)
    for name in ("threads", "workers", "threads_per_worker", "chunk"):
        if getattr(a, name) is not None and getattr(a, name) < 1:
            ap.error(f"--{name.replace('_', '-')} must be >= 1")
    a.fill_options = {}
    for flag, name in _FLAG_OPTIONS.items():
        if getattr(a, name) is not None:
            a.fill_options[name] = getattr(a, name)
    if a.inner:
        a.fill_options["INNER_ONLY"] = "YES"
    if a.maxvoid is not None:
        a.fill_options["MAX_VOID"] = a.maxvoid
    for o in a.options:
        if "=" not in o:
            ap.error(f"-o expects NAME=VALUE, got {o!r}")
        name, value = o.split("=", 1)
        a.fill_options[name.strip().upper()] = value
    return a


def main(argv=None) -> int:
    a = parse(argv)
    from .. import Error
    try:
        run(a)
    except (Failure, Error, ValueError, OSError, RuntimeError) as e:
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
        raise Failure(f"cannot open '{a.src}': {e}") from None
    bands = a.bands or [b for b in range(1, src.RasterCount + 1)
                        if src.GetRasterBand(b).GetColorInterpretation() != gdal.GCI_AlphaBand]
    for b in bands:
        if not 1 <= b <= src.RasterCount:
            raise Failure(f"band {b} does not exist: '{a.src}' has {src.RasterCount} band(s)")
    zarr = a.dst.rstrip("/").endswith(".zarr")
    dst_dir = os.path.dirname(os.path.abspath(a.dst))
    if not os.path.isdir(dst_dir):
        raise Failure(f"cannot write '{a.dst}': folder '{dst_dir}' does not exist")
    if os.path.isdir(a.dst) and not zarr:
        raise Failure(f"cannot write '{a.dst}': it is a folder")
    options = check_options(a, src)  # before any cluster starts
    graphs = {b: band(a, src, b, options) for b in bands}
    tmp = os.path.join(dst_dir, f".{os.path.basename(a.dst.rstrip('/'))}.mcmd-tmp-{os.getpid()}")
    try:
        if a.threads is not None or (a.workers is None and a.scheduler is None):
            on_threads(a, src, graphs, tmp, zarr)
        else:
            on_cluster(a, src, graphs, tmp, zarr)
        replace(tmp, a.dst)
    finally:
        remove(tmp)


def check_options(a, src) -> list:
    """The fill's NAME=VALUE options, checked by the library's parser (the
    CLI's messages); a void cap given as an area becomes cells of SRC, as
    the CLI converts it."""
    from .. import _options
    from .._mcmd import chunk_grid, max_void_cells
    for name, value in a.fill_options.items():
        if name in _FLAGS_OF and (name != "MORPH" or value.strip().upper() == "AUTO"):
            raise Failure(f"{_FLAGS_OF[name]} needs the whole raster at once: use mcmd_fillnodata for it")
    options = _options.fill_options(a.fill_options, caller="mcmd.dask")
    cells = max_void_cells(options, a.src)
    if cells:
        a.fill_options["MAX_VOID"] = f"{cells}cells"
        options = _options.fill_options(a.fill_options, caller="mcmd.dask")
    chunk_grid(src.RasterXSize, src.RasterYSize, options)
    return options


def band(a, src, b: int, options: list) -> tuple:
    """(graph, output chunks, gathered summaries' key, dtype, token) of band b's fill."""
    import dask.base
    from osgeo import gdal
    from . import _file
    stat = os.stat(a.src)
    # This run's own token: a worker that served an earlier run starts afresh
    # (its plan and its decoded blocks of SRC are not reused: _steps.forget).
    token = dask.base.tokenize(os.path.abspath(a.src), stat.st_mtime_ns, stat.st_size, b, options, uuid.uuid4().hex)
    spec, dtype = _file.source_spec(a.src, b, options, token)
    sb = src.GetRasterBand(b)
    marked = spec.nodata is not None or dtype.kind == "f" or not sb.GetMaskFlags() & gdal.GMF_ALL_VALID
    if not marked:
        raise Failure(f"band {b} has no nodata value, mask or NaN cell: nothing marks the voids "
                      "(set a nodata value, e.g. gdal_edit.py -a_nodata)")
    dsk, out, gather_key = _file.band_graph(a.src, b, spec, a.chunk, hold=holds(spec, dtype))
    return dsk, out, gather_key, dtype, token


def holds(spec, dtype) -> bool:
    """Whether each chunk is read once and held from its summary to its
    blend (rasters up to an eighth of this machine's memory), rather than
    read again by each step."""
    pages = os.sysconf("SC_PHYS_PAGES") * os.sysconf("SC_PAGE_SIZE")
    return spec.width * spec.height * dtype.itemsize * 2 <= pages // 8


def on_threads(a, src, graphs, tmp, zarr) -> None:
    """Dask's threaded scheduler in this process; each filled chunk is
    written by a task of its own as soon as it is done."""
    import dask
    import dask.threaded
    lock = threading.Lock()
    dsk, stores = {}, []
    writer = zarr_writer(src, graphs, tmp) if zarr else geotiff_writer(a, src, graphs, tmp)

    def store(b, x0, y0, block):
        with lock:
            writer.write(b, x0, y0, block)

    for b, (graph, out, _, _, _) in graphs.items():
        dsk.update(graph)
        for k, (key, x0, y0) in enumerate(out):
            stores.append((f"mcmd-store-{b}", k))
            dsk[stores[-1]] = (store, b, x0, y0, key)
    with dask.config.set(num_workers=a.threads or os.cpu_count()):
        if a.quiet:
            dask.threaded.get(dsk, stores)
        else:
            from dask.diagnostics import ProgressBar
            with ProgressBar():
                dask.threaded.get(dsk, stores)
    writer.close()


def on_cluster(a, src, graphs, tmp, zarr) -> None:
    """A dask.distributed cluster: chunks written as they arrive (the client
    holds one at a time)."""
    from distributed import Client, as_completed, progress
    from . import _file
    cluster = None
    if a.scheduler:
        client = Client(a.scheduler)
    else:
        from ._cluster import local_cluster
        cluster = local_cluster(a.workers, a.threads_per_worker)
        client = Client(cluster)
    try:
        writer = zarr_writer(src, graphs, tmp) if zarr else geotiff_writer(a, src, graphs, tmp)
        futures, where = [], {}
        for b, (graph, out, gather_key, _, _) in graphs.items():
            if gather_key is None:
                fs = client.get(graph, [key for key, _, _ in out], sync=False)
            else:
                fs = _file.on_client(client, graph, out, gather_key)
            for f, (_, x0, y0) in zip(fs, out):
                where[f.key] = (b, x0, y0)
            futures += fs
        failed = []

        def write_all():  # GDAL's dataset stays on this one thread
            try:
                for future in as_completed(futures):
                    writer.write(*where[future.key], future.result())
                    future.release()
            except BaseException as e:  # noqa: BLE001  (raised again on the calling thread)
                failed.append(e)

        thread = threading.Thread(target=write_all, name="mcmd.dask writer")
        thread.start()
        if not a.quiet:
            progress(futures)  # Dask's text progress bar, until every chunk is computed
            print()
        thread.join()
        if failed:
            raise failed[0]
        writer.close()
    finally:
        release(client, [token for *_, token in graphs.values()])
        client.close()
        if cluster is not None:
            cluster.close()


def release(client, tokens: list) -> None:
    """The workers let go of this run's plans and open files (and so of
    GDAL's decoded blocks of SRC)."""
    from . import _steps
    try:
        client.run(_steps.forget, tokens)
    except Exception:  # noqa: BLE001  (a worker gone: its caches went with it)
        pass


class geotiff_writer:
    """The output GeoTIFF: SRC's size, type, georeferencing, metadata, and
    per band its nodata value, description, colour, unit, offset, scale and
    metadata; the bands not filled are copied."""

    def __init__(self, a, src, graphs, tmp):
        from osgeo import gdal
        W, H, n = src.RasterXSize, src.RasterYSize, src.RasterCount
        options = ["TILED=YES", "BIGTIFF=IF_SAFER"] + list(a.creation)
        out = gdal.GetDriverByName("GTiff").Create(tmp, W, H, n, src.GetRasterBand(1).DataType, options)
        if src.GetGeoTransform(can_return_null=True) is not None:
            out.SetGeoTransform(src.GetGeoTransform())
        if src.GetProjection():
            out.SetProjection(src.GetProjection())
        out.SetMetadata(src.GetMetadata())
        for b in range(1, n + 1):
            sb, ob = src.GetRasterBand(b), out.GetRasterBand(b)
            copy_band_fields(sb, ob)
            if b not in graphs:  # copied as it is, in row strips
                rows = max(1, (1 << 22) // max(W, 1))
                for y in range(0, H, rows):
                    ob.WriteArray(sb.ReadAsArray(0, y, W, min(rows, H - y)), 0, y)
        self.out = out

    def write(self, b, x0, y0, block):
        self.out.GetRasterBand(b).WriteArray(block, x0, y0)

    def close(self):
        self.out.FlushCache()
        self.out = None


def copy_band_fields(sb, ob) -> None:
    if sb.GetNoDataValue() is not None:
        ob.SetNoDataValue(sb.GetNoDataValue())
    ob.SetColorInterpretation(sb.GetColorInterpretation())
    ob.SetDescription(sb.GetDescription())
    ob.SetMetadata(sb.GetMetadata())
    if sb.GetUnitType():
        ob.SetUnitType(sb.GetUnitType())
    if sb.GetOffset() not in (None, 0.0):
        ob.SetOffset(sb.GetOffset())
    if sb.GetScale() not in (None, 1.0):
        ob.SetScale(sb.GetScale())


class zarr_writer:
    """The output Zarr store as xarray and rioxarray read it: one array
    band_B (y, x) per filled band, its coordinates, CRS and nodata."""

    def __init__(self, src, graphs, tmp):
        import numpy as np
        import zarr
        W, H = src.RasterXSize, src.RasterYSize
        root = zarr.open_group(tmp, mode="w")
        gt = src.GetGeoTransform(can_return_null=True) or (0.0, 1.0, 0.0, 0.0, 0.0, 1.0)
        for name, n, origin, size in (("x", W, gt[0], gt[1]), ("y", H, gt[3], gt[5])):
            coord = root.create_dataset(name, data=origin + (np.arange(n) + 0.5) * size, overwrite=True)
            coord.attrs["_ARRAY_DIMENSIONS"] = [name]
        crs = root.create_dataset("spatial_ref", shape=(), dtype="i8", fill_value=0)
        crs.attrs.update({"_ARRAY_DIMENSIONS": [], "crs_wkt": src.GetProjection(), "spatial_ref": src.GetProjection(),
                          "GeoTransform": " ".join(repr(v) for v in gt)})
        self.arrays = {}
        for b, (graph, out, _, dtype, _) in graphs.items():
            sb = src.GetRasterBand(b)
            chunks = (min((y0 for _, _, y0 in out if y0 > 0), default=H),
                      min((x0 for _, x0, _ in out if x0 > 0), default=W))
            arr = root.create_dataset(f"band_{b}", shape=(H, W), chunks=chunks, dtype=dtype, fill_value=None)
            attrs = {"_ARRAY_DIMENSIONS": ["y", "x"], "grid_mapping": "spatial_ref"}
            if sb.GetNoDataValue() is not None:
                attrs["nodata"] = sb.GetNoDataValue()
            arr.attrs.update(attrs)
            self.arrays[b] = arr
        self.root = root

    def write(self, b, x0, y0, block):
        self.arrays[b][y0:y0 + block.shape[0], x0:x0 + block.shape[1]] = block

    def close(self):
        import zarr
        zarr.consolidate_metadata(self.root.store)


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
