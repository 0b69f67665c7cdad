"""mcmd.dask.fill on dask arrays and DataArrays: the graph of its four steps
(docs/dask.md) built from dask.array's chunks."""
from __future__ import annotations

from typing import Any, Optional

import dask
import dask.array as da
import numpy as np

from .. import _arrays, _options
from .._fill import is_dataarray, rasterio_keywords
from .._mcmd import chunk_grid, fills_whole
from . import _steps
from ._file import edges

# Options the chunked fill cannot honour: they judge or read the raster as a whole.
_WHOLE_RASTER_OPTIONS = {"FILL_FROM", "FILL_FROM_RESAMPLING", "RIVERS", "RIDGES"}


def fill(data: Any, mask: Any = None, nodata: Any = None, *, method: str = "mcmd", rs: float | str = 0.0,
         seed: int = 0, max_distance: float = 0, chunks: Optional[int] = None, **options: Any) -> Any:
    """mcmd.dask.fill (its docstring says what it does)."""
    xarr = _as_dataarray(data)
    arr = xarr.data if xarr is not None else data
    if not isinstance(arr, da.Array):
        arr = da.from_array(np.asarray(arr), chunks="auto")
    if arr.ndim not in (2, 3):
        raise ValueError(f"expected a 2-D (rows, columns) or 3-D (bands, rows, columns) array, got {arr.ndim}-D "
                         f"of shape {arr.shape}")
    if 0 in arr.shape:
        raise ValueError(f"the array is empty (shape {arr.shape})")
    _arrays.check_dtype(arr.dtype)
    if nodata is None and xarr is not None:
        from ..xarray import nodata_of
        nodata = nodata_of(xarr)
    max_distance = rasterio_keywords(options, max_distance, "mcmd.dask.fill")
    named = {"METHOD": ("method", method), "RS": ("rs", rs), "SEED": ("seed", seed),
             "MAX_DISTANCE": ("max_distance", max_distance)}
    opts = _options.fill_options(options, named, caller="mcmd.dask.fill")
    marr = _mask_array(mask, arr)
    bands = [arr] if arr.ndim == 2 else [arr[k] for k in range(arr.shape[0])]
    nodatas = [_arrays.nodata_value(v, arr.dtype) for v in _arrays.band_nodata(nodata, len(bands))]
    masks = [marr if marr is None or marr.ndim == 2 else marr[k] for k in range(len(bands))]
    filled = [_fill_band(band, m, nd, opts, chunks) for band, m, nd in zip(bands, masks, nodatas)]
    out = filled[0] if arr.ndim == 2 else da.stack(filled)
    return xarr.copy(data=out) if xarr is not None else out


def _fill_band(arr: da.Array, marr: Optional[da.Array], nd: Any, opts: list, chunks: Optional[int]) -> da.Array:
    if marr is None and nd is None and arr.dtype.kind != "f":
        raise ValueError("the array has no nodata value or mask and cannot hold NaN: nothing marks the voids "
                         "(pass nodata= or mask=)")
    height, width = arr.shape
    step, min_side, margin, whole = chunk_grid(width, height, opts)  # checks the options: the CLI's messages
    for o in opts:
        name, value = o.split("=", 1)
        if name.upper() in _WHOLE_RASTER_OPTIONS:
            raise ValueError(f"mcmd.dask.fill cannot use {name.upper()}: it reads another file whole "
                             f"(use mcmd.fill_file)")
        if name.upper() == "MORPH" and value.strip().upper() == "AUTO":
            raise ValueError("mcmd.dask.fill cannot use MORPH=auto: its channels follow the drainage of the whole "
                             "raster (use mcmd.fill_file, or mcmd.fill on an array)")
    spec = _steps.Spec(width, height, arr.dtype.str, _arrays.gdal_type(arr.dtype), nd, opts,
                       dask.base.tokenize(arr, marr, nd, opts))
    if whole or fills_whole(width, height, opts):
        return _whole(arr, marr, spec)
    side = _chunk_side(chunks, arr, step, min_side)
    return _chunked(arr, marr, spec, side, min_side, margin)


def _as_dataarray(data: Any):
    if not is_dataarray(data):
        return None
    from ..xarray import check_dims
    check_dims(data)
    return data


def _mask_array(mask: Any, arr: da.Array) -> Optional[da.Array]:
    if mask is None:
        return None
    m = mask.data if is_dataarray(mask) else mask
    if not isinstance(m, da.Array):
        m = np.asarray(m)
    if m.shape != arr.shape and not (arr.ndim == 3 and m.shape == arr.shape[1:]):
        raise ValueError(f"the mask has shape {m.shape} but the array has shape {arr.shape}")
    if m.dtype.kind not in "biuf":
        raise ValueError(f"mask dtype {m.dtype} is not supported: expected bool or a number (0 = void)")
    return m if isinstance(m, da.Array) else da.from_array(m, chunks=arr.chunks[-m.ndim:])


def _chunk_side(chunks: Optional[int], arr: da.Array, step: int, min_side: int) -> int:
    want = chunks if chunks is not None else max(arr.chunks[0][0], arr.chunks[1][0])
    if not isinstance(want, (int, np.integer)) or want < 1:
        raise ValueError(f"chunks must be a positive number of cells, got {chunks!r}")
    side = max(int(want), min_side)
    return -(-side // step) * step


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
    ys, xs = edges(spec.height, side, min_side), edges(spec.width, side, min_side)
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
