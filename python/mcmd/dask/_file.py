"""The fill of a raster file's band as a Dask task graph whose tasks read
their own windows with GDAL (python3 -m mcmd.dask).

Nothing read travels between processes: a chunk's tasks read the chunk and
its margin from the file (every worker sees the file, as every worker of a
cluster reading a mosaic does). When the raster is small beside the memory
at hand, each chunk is read once and held from its summary to its blend;
otherwise each step reads it again, and memory stays bounded by the chunks
in flight. On a cluster, a chunk's solve and blend run where its read lies, so only
the summaries, the gathered summaries (once to each worker) and the edges
of solutions cross the network.
"""
from __future__ import annotations

from typing import Any, Optional

from . import _steps
from .._mcmd import chunk_grid, fills_whole


def band_graph(path: str, band: int, spec: _steps.Spec, chunk: int, hold: bool) -> tuple[dict, list, list]:
    """(graph, output chunks as (key, x0, y0), the key of the gathered
    summaries or None) for band `band` of `path` filled as `spec` says."""
    W, H = spec.width, spec.height
    step, min_side, margin, whole = chunk_grid(W, H, spec.options)
    name = f"mcmd-{spec.token}-b{band}"
    if whole or fills_whole(W, H, spec.options):
        key = (f"{name}-whole", 0, 0)
        return {key: (_steps.whole, _steps.Window(path, band, 0, 0, W, H), None, spec)}, [(key, 0, 0)], None
    side = -(-max(chunk, min_side) // step) * step
    ys, xs = edges(H, side, min_side), edges(W, side, min_side)
    ny, nx = len(ys) - 1, len(xs) - 1
    dsk: dict = {}
    gather_key = f"{name}-gather"
    own, origin, source = {}, {}, {}
    for j in range(ny):
        for i in range(nx):
            own[j, i] = (xs[i], ys[j], xs[i + 1] - xs[i], ys[j + 1] - ys[j])
            x0, y0 = max(0, xs[i] - margin), max(0, ys[j] - margin)
            x1, y1 = min(W, xs[i + 1] + margin), min(H, ys[j + 1] + margin)
            origin[j, i] = (x0, y0)
            window = _steps.Window(path, band, x0, y0, x1 - x0, y1 - y0)
            if hold:
                source[j, i] = (f"{name}-read", j, i)
                dsk[source[j, i]] = (_steps.read, window, spec)
            else:
                source[j, i] = window
            key = (f"{name}-summary", j, i)
            dsk[key] = (_steps.summarize, source[j, i], None, spec, origin[j, i], own[j, i])
    dsk[gather_key] = (_steps.gather, *[(f"{name}-summary", j, i) for j in range(ny) for i in range(nx)])
    for (j, i), o in own.items():
        key = (f"{name}-solve", j, i)
        dsk[key] = (_steps.solve, gather_key, source[j, i], None, spec, origin[j, i], o)
    out = []
    for (j, i), o in own.items():
        around = []
        for b in range(max(0, j - 1), min(ny, j + 2)):
            for a in range(max(0, i - 1), min(nx, i + 2)):
                if (a, b) == (i, j):
                    around.append((f"{name}-solve", b, a))
                else:  # cut where the solution lies: only the part travels
                    key = (f"{name}-part-{j}-{i}", b, a)
                    dsk[key] = (_steps.part, (f"{name}-solve", b, a), o)
                    around.append(key)
        if hold:
            cells = (f"{name}-crop", j, i)
            dsk[cells] = (_steps.crop, source[j, i], origin[j, i], o)
        else:
            cells = _steps.Window(path, band, *o)
        key = (f"{name}-blend", j, i)
        dsk[key] = (_steps.blend, gather_key, cells, None, spec, o, *around)
        out.append((key, o[0], o[1]))
    return dsk, out, gather_key


def edges(length: int, side: int, min_side: int) -> list:
    """Chunk edges: multiples of side; a short last chunk joins the one before."""
    e = list(range(0, length, side))
    if len(e) > 1 and length - e[-1] < min_side:
        e.pop()
    return e + [length]


def on_client(client, dsk: dict, out: list, gather_key: str) -> list:
    """Futures of the output chunks of `dsk` computed on a distributed
    client in two rounds: the summaries (and the reads held) first, then,
    the gathered summaries copied to every worker, the rest. Each chunk's
    solve and blend then run where its read lies rather than where the
    summaries were gathered, and no worker waits for them in turn."""
    first = {k: v for k, v in dsk.items() if key_step(k) in ("read", "summary")}
    first[gather_key] = dsk[gather_key]
    held = [k for k in first if key_step(k) == "read"]
    futures = dict(zip(held + [gather_key], client.get(first, held + [gather_key], sync=False)))
    client.replicate([futures[gather_key]])
    rest = {k: v for k, v in dsk.items() if k not in first}
    rest.update(futures)  # futures in a graph: their results, where they lie
    return client.get(rest, [key for key, _, _ in out], sync=False)


def key_step(key) -> str:
    """The step of a task key: read, summary, gather, solve, part, crop, blend, whole."""
    name = key if isinstance(key, str) else key[0]
    return name.rsplit("-", 3)[-3] if "-part-" in name else name.rsplit("-", 1)[-1]


def source_spec(path: str, band: int, options: list, token: str) -> tuple:
    """(Spec, numpy dtype) of band `band` of `path`: its size, type and nodata."""
    import numpy as np
    from osgeo import gdal, gdal_array
    from .. import _arrays
    ds = gdal.Open(path)
    b = ds.GetRasterBand(band)
    if b.DataType == gdal.GDT_Byte and b.GetMetadataItem("PIXELTYPE", "IMAGE_STRUCTURE") == "SIGNEDBYTE":
        dtype = np.dtype(np.int8)
    else:
        dtype = np.dtype(gdal_array.GDALTypeCodeToNumericTypeCode(b.DataType))
    _arrays.check_dtype(dtype)
    if b.DataType == gdal.GDT_Int64:
        nodata: Optional[Any] = b.GetNoDataValueAsInt64()
    elif b.DataType == gdal.GDT_UInt64:
        nodata = b.GetNoDataValueAsUInt64()
    else:
        nodata = b.GetNoDataValue()
    if nodata is not None:
        nodata = int(nodata) if dtype.kind in "iu" else float(nodata)
    spec = _steps.Spec(ds.RasterXSize, ds.RasterYSize, dtype.str, _arrays.gdal_type(dtype), nodata, list(options),
                       token)
    return spec, dtype
