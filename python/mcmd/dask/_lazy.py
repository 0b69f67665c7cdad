"""Region-scale fills on Dask: ``mcmd.dask.fill`` returns a lazy filled array.

The fill is the CLI's tiled fill split into chunks whose sides are multiples
of the tile step (tile size - 1). The graph has four steps (docs/dask.md):

1. per chunk, a summary: its void cells, its known range and the coarse
   guide's sums over the chunk (a block read with a margin around it);
2. one task gathers the summaries; each worker builds the plan from them once
   (the guide's solve, the small voids, the list of windows);
3. per chunk, the windows of the tiles it owns and its small voids, solved;
4. per chunk, its cells blended from its own solution and the parts of its
   8 neighbours' that reach into it (cut where they lie: only those travel).

For the same options (tile size included), the result is bit-identical to
``mcmd_fillnodata``'s on the same raster, whatever the chunking, the number
of workers or the scheduler. Rasters the CLI fills whole (the default method
on at most 2^21 cells, unless ``tiling="ALWAYS"``) are filled whole, in one
task, by the same code.

``python3 -m mcmd.dask SRC DST`` fills a file on a cluster (``--help``).
"""
from __future__ import annotations

from typing import Any, Optional

import dask
import dask.array as da
import numpy as np

from .. import _arrays, _options
from .._mcmd import chunk_grid, fills_whole
from . import _steps

__all__ = ["fill"]

# Options the chunked fill cannot honour: they judge or read the raster as a whole.
_WHOLE_RASTER_OPTIONS = {"FILL_FROM", "FILL_FROM_RESAMPLING", "RIVERS", "RIDGES"}


def fill(data: Any, mask: Any = None, nodata: int | float | None = None, *, method: str = "mcmd",
         rs: float | str = 0.0, seed: int = 0, max_distance: float = 0, chunks: Optional[int] = None,
         **options: Any) -> Any:
    """Fill the voids of a 2-D dask array or xarray.DataArray, lazily.

    Parameters
    ----------
    data : dask.array.Array, xarray.DataArray or array_like, 2-D (rows, columns)
        Any dtype :func:`mcmd.fill` takes. A DataArray keeps its coordinates,
        attributes and rioxarray fields; its nodata value is
        ``data.rio.nodata`` (or the ``_FillValue`` attribute) unless given.
    mask : same shape, optional
        Validity mask, true / non-zero = valid (as :func:`mcmd.fill`).
    nodata : number, optional
        Cells equal to it are voids.
    method, rs, seed, max_distance, **options
        As for :func:`mcmd.fill` (``tile_size=``, ``tiling=``, ``H=``,
        ``inner_only=True``, ``max_void=5000`` in cells...). ``fill_from``,
        ``rivers`` and ``ridges`` read other files whole: use
        :func:`mcmd.fill_file`.
    chunks : int, optional
        Side of the fill's chunks, rounded up to a multiple of the tile step
        (default: the input's first chunk, rounded likewise). The data are
        rechunked to it; the result does not depend on it.

    Returns
    -------
    The same kind as ``data`` (a dask array for array input), lazy, with the
    dtype of ``data``; valid cells bit-exact.

    Raises
    ------
    ValueError
        Not 2-D, an unsupported dtype, a mask of another shape, nothing
        marking the voids of an integer raster, a bad or whole-raster option.
    mcmd.Error
        At compute time: no valid cell to fill from.
    """
    xarr = _as_dataarray(data)
    arr = xarr.data if xarr is not None else data
    if not isinstance(arr, da.Array):
        arr = da.from_array(np.asarray(arr), chunks="auto")
    if arr.ndim != 2:
        raise ValueError(f"expected a 2-D array (rows, columns), got {arr.ndim}-D of shape {arr.shape}")
    if 0 in arr.shape:
        raise ValueError(f"the array is empty (shape {arr.shape})")
    gdal_type = _arrays.gdal_type(arr.dtype)
    if nodata is None and xarr is not None:
        nodata = _nodata_of(xarr)
    nd = _arrays.nodata_value(nodata, arr.dtype)
    marr = _mask_array(mask, arr)
    if marr is None and nd is None and arr.dtype.kind != "f":
        raise ValueError("the array has no nodata value or mask and cannot hold NaN: nothing marks the voids "
                         "(pass nodata= or mask=)")
    named = {"METHOD": ("method", method), "RS": ("rs", rs), "SEED": ("seed", seed),
             "MAX_DISTANCE": ("max_distance", max_distance)}
    opts = _options.fill_options(options, named, caller="mcmd.dask.fill")
    for o in opts:
        if o.split("=", 1)[0].upper() in _WHOLE_RASTER_OPTIONS:
            raise ValueError(f"mcmd.dask.fill cannot use {o.split('=', 1)[0].upper()}: it reads another file "
                             f"whole (use mcmd.fill_file)")
    height, width = arr.shape
    spec = _steps.Spec(width, height, arr.dtype.name if arr.dtype.isnative else arr.dtype.str, gdal_type, nd,
                       opts, dask.base.tokenize(arr, marr, gdal_type, nd, opts))
    step, min_side, margin, whole = chunk_grid(width, height, opts)
    if whole or fills_whole(width, height, opts):
        out = _whole(arr, marr, spec)
    else:
        side = _chunk_side(chunks, arr, step, min_side)
        out = _chunked(arr, marr, spec, side, min_side, margin)
    return xarr.copy(data=out) if xarr is not None else out


def _as_dataarray(data: Any):
    try:
        import xarray
    except ImportError:  # xarray is optional: arrays work without it
        return None
    return data if isinstance(data, xarray.DataArray) else None


def _nodata_of(xarr) -> Any:
    try:
        import rioxarray  # noqa: F401  (registers the .rio accessor)
        nd = xarr.rio.nodata
        if nd is not None and not (isinstance(nd, float) and np.isnan(nd)):
            return nd.item() if hasattr(nd, "item") else nd
    except ImportError:
        pass
    nd = xarr.attrs.get("_FillValue", xarr.encoding.get("_FillValue"))
    return None if nd is None or (isinstance(nd, float) and np.isnan(nd)) else nd


def _mask_array(mask: Any, arr: da.Array) -> Optional[da.Array]:
    if mask is None:
        return None
    m = mask.data if _as_dataarray(mask) is not None else mask
    if not isinstance(m, da.Array):
        m = np.asarray(m)
    if m.shape != arr.shape:
        raise ValueError(f"the mask has shape {m.shape} but the array has shape {arr.shape}")
    if m.dtype.kind not in "biuf":
        raise ValueError(f"mask dtype {m.dtype} is not supported: expected bool or a number (0 = void)")
    return m if isinstance(m, da.Array) else da.from_array(m, chunks=arr.chunks)


def _chunk_side(chunks: Optional[int], arr: da.Array, step: int, min_side: int) -> int:
    want = chunks if chunks is not None else max(arr.chunks[0][0], arr.chunks[1][0])
    if not isinstance(want, (int, np.integer)) or want < 1:
        raise ValueError(f"chunks must be a positive number of cells, got {chunks!r}")
    side = max(int(want), min_side)
    return -(-side // step) * step


def _edges(length: int, side: int, min_side: int) -> list:
    """Chunk edges: multiples of side; a short last chunk joins the one before."""
    e = list(range(0, length, side))
    if len(e) > 1 and length - e[-1] < min_side:
        e.pop()
    return e + [length]


def _blocks(a: Optional[da.Array], shape) -> np.ndarray:
    if a is None:
        return np.full(shape, None, dtype=object)
    return a.to_delayed()


def _whole(arr: da.Array, marr: Optional[da.Array], spec: _steps.Spec) -> da.Array:
    block = arr.rechunk(arr.shape).to_delayed()[0, 0]
    mblock = None if marr is None else marr.rechunk(marr.shape).to_delayed()[0, 0]
    task = dask.delayed(_steps.whole, pure=True)(block, mblock, spec)
    return da.from_delayed(task, shape=arr.shape, dtype=arr.dtype)


def _chunked(arr: da.Array, marr: Optional[da.Array], spec: _steps.Spec, side: int, min_side: int,
             margin: int) -> da.Array:
    ys, xs = _edges(spec.height, side, min_side), _edges(spec.width, side, min_side)
    rows, cols = tuple(np.diff(ys)), tuple(np.diff(xs))
    arr = arr.rechunk((rows, cols))
    marr = None if marr is None else marr.rechunk((rows, cols))
    depth = {0: margin, 1: margin}
    grown = da.overlap.overlap(arr, depth=depth, boundary="none")
    mgrown = None if marr is None else da.overlap.overlap(marr, depth=depth, boundary="none")
    ny, nx = len(rows), len(cols)
    gb, mgb = _blocks(grown, (ny, nx)), _blocks(mgrown, (ny, nx))
    ob, mob = arr.to_delayed(), _blocks(marr, (ny, nx))
    delayed = lambda f: dask.delayed(f, pure=True)  # noqa: E731
    own = [[(xs[i], ys[j], xs[i + 1] - xs[i], ys[j + 1] - ys[j]) for i in range(nx)] for j in range(ny)]
    origin = [[(max(0, xs[i] - margin), max(0, ys[j] - margin)) for i in range(nx)] for j in range(ny)]
    summaries = [delayed(_steps.summarize)(gb[j, i], mgb[j, i], spec, origin[j][i], own[j][i])
                 for j in range(ny) for i in range(nx)]
    gathered = delayed(_steps.gather)(*summaries)
    solved = [[delayed(_steps.solve)(gathered, gb[j, i], mgb[j, i], spec, origin[j][i], own[j][i])
               for i in range(nx)] for j in range(ny)]
    out = []
    for j in range(ny):
        row = []
        for i in range(nx):
            around = [solved[b][a] if (a, b) == (i, j) else delayed(_steps.part)(solved[b][a], own[j][i])
                      for b in range(max(0, j - 1), min(ny, j + 2)) for a in range(max(0, i - 1), min(nx, i + 2))]
            task = delayed(_steps.blend)(gathered, ob[j, i], mob[j, i], spec, own[j][i], *around)
            row.append(da.from_delayed(task, shape=(rows[j], cols[i]), dtype=arr.dtype))
        out.append(row)
    return da.block(out)
