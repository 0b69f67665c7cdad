"""mcmd.fill on what the Python raster stack hands over: a band (rows,
columns), bands (bands, rows, columns) as rasterio's ``read()`` returns them,
a numpy masked array (masked out where voids stay unfilled) and an
xarray.DataArray (mcmd.xarray)."""
from __future__ import annotations

import numbers
from typing import Any, Callable, Optional

import numpy as np

from . import _arrays, _options
from ._mcmd import fill_array as _fill_array

Progress = Callable[[float], Optional[bool]]


def fill(array: Any, mask: Any = None, nodata: Any = None, *, method: str = "mcmd", rs: float | str = 0.0,
         seed: int = 0, max_distance: float = 0, threads: int | None = None, progress: Progress | None = None,
         **options: Any) -> Any:
    """Fill the voids of a raster array; return a new one of the same kind and dtype.

    Parameters
    ----------
    array : array_like (rows, columns) or (bands, rows, columns), or xarray.DataArray
        uint8, int8, uint16, int16, uint32, int32, uint64, int64, float16,
        float32 or float64 (float16 is filled as float32 and rounded back).
        Not modified. A 3-D array is filled band by band, as the CLI fills
        the bands of a file. A numpy masked array's masked cells are voids,
        and the result is a masked array masking the voids left unfilled. A
        DataArray gives a DataArray with its coordinates, CRS and attributes.
    mask : array_like of bool or numbers, optional
        Validity mask as in rasterio's ``fillnodata``: true / non-zero =
        valid, false / 0 = void (like the CLI's ``-mask`` file). Of the
        array's shape, or (rows, columns) for every band.
    nodata : number or one number per band, optional
        Cells equal to it are voids, and no filled cell is given this value.
        The dtype must hold it exactly (ValueError otherwise).
    method : {"mcmd", "paper-ds", "paper-te"}
        ``mcmd`` (default): a smooth, thin-plate-like fill; ``paper-ds`` /
        ``paper-te``: the published MCMD method exactly.
    rs : float or "auto"
        Roughness, a fraction of the known elevation range (0 = smooth);
        ``"auto"`` matches the roughness of the terrain around each void.
    seed : int
        Seed of the roughness noise: the same seed gives the same bits.
    max_distance : float
        Voids farther than this many cells from a valid cell are left as they
        are (0 = fill every void). rasterio's ``max_search_distance`` is
        taken as this.
    threads : int, optional
        Worker threads (default: all CPUs). The result does not depend on it.
    progress : callable(fraction) -> bool | None, optional
        Called from the calling thread with the fraction done (at most about
        ten times a second, and at the end); returning False cancels.
    **options
        Any other library option by name, in any case (``tiling="ALWAYS"``,
        ``tile_size=257``, ``H=0.6``, ``I=0.3``, ``delta="paper"``...).
        rasterio's ``smoothing_iterations`` is accepted and not needed: the
        fill is smooth where it meets the known cells.

    Voids are NaN and infinite cells (float arrays), cells equal to
    ``nodata`` and cells where ``mask`` is false. Integer results are rounded
    and clamped to the dtype exactly as the CLI writes them.

    Raises
    ------
    ValueError
        Not a 2-D or 3-D array of a supported dtype, a mask of another
        shape, a nodata value the dtype cannot hold, nothing marking the
        voids, a bad option (the CLI's message).
    mcmd.Error
        No valid cell to fill from.
    mcmd.Cancelled
        ``progress`` returned False.
    """
    if is_dataarray(array):
        from . import xarray as mx
        return mx.fill_now(array, mask, nodata, method=method, rs=rs, seed=seed, max_distance=max_distance,
                           threads=threads, progress=progress, **options)
    max_distance = rasterio_keywords(options, max_distance, "fill")
    data = _arrays.raster(array, dims=(2, 3))
    valid = _arrays.valid_mask(mask, data, array)
    bands = data[None] if data.ndim == 2 else data
    nodatas = [_arrays.nodata_value(v, data.dtype) for v in _arrays.band_nodata(nodata, len(bands))]
    for k, band in enumerate(bands):
        band_valid = None if valid is None else (valid if data.ndim == 2 else valid[k])
        if band_valid is None and nodatas[k] is None and not _arrays.has_nonfinite(band):
            where = "the array" if data.ndim == 2 else f"band {k + 1} of the array"
            raise ValueError(f"{where} has no nodata value, mask or NaN cell: nothing marks the voids "
                             "(pass nodata= or mask=)")
    named = {"METHOD": ("method", method), "RS": ("rs", rs), "SEED": ("seed", seed),
             "MAX_DISTANCE": ("max_distance", max_distance), "NUM_THREADS": ("threads", threads)}
    opts = _options.fill_options(options, named, caller="fill")
    check_progress(progress)
    masked = isinstance(array, np.ma.MaskedArray)
    outs, lefts = [], []
    for k, band in enumerate(bands):
        band_valid = None if valid is None else (valid if data.ndim == 2 else valid[k])
        out, left = fill_band(band, band_valid, nodatas[k], opts, band_progress(progress, k, len(bands)), masked)
        outs.append(out)
        lefts.append(left)
    out = outs[0] if data.ndim == 2 else np.stack(outs)
    if not masked:
        return out
    left = lefts[0] if data.ndim == 2 else np.stack(lefts)
    fill_value = nodatas[0] if nodatas[0] is not None and len(set(nodatas)) == 1 else array.fill_value
    return np.ma.MaskedArray(out, mask=left, fill_value=fill_value)


def fill_band(band: np.ndarray, valid: np.ndarray | None, nodata: Any, opts: list, progress: Progress | None,
              want_left: bool) -> tuple[np.ndarray, np.ndarray | None]:
    """One band filled: (the filled band, the voids left unfilled or None).
    With want_left, the voids left unfilled hold `nodata` when there is one."""
    work = _arrays.native_copy(band)
    filled = np.zeros(band.shape, np.uint8) if want_left else None
    _fill_array(work, valid, _arrays.gdal_type(band.dtype), nodata, opts, progress, filled)
    out = _arrays.to_dtype(work, band.dtype, nodata)
    if not want_left:
        return out, None
    left = _arrays.voids(band, valid, nodata) & (filled == 0)
    if nodata is not None:
        out[left] = nodata
    return out, left


def band_progress(progress: Progress | None, k: int, n: int) -> Progress | None:
    """Band k of n's share of the whole fill's progress."""
    if progress is None or n == 1:
        return progress
    return lambda fraction: progress((k + fraction) / n)


def rasterio_keywords(options: dict, max_distance: float, caller: str) -> float:
    """rasterio.fill.fillnodata's keywords, taken out of `options`:
    max_search_distance is max_distance; smoothing_iterations is checked and
    not needed (the fill is smooth where it meets the known cells)."""
    keys = {k.lower(): k for k in options}
    if "max_search_distance" in keys:
        value = options.pop(keys["max_search_distance"])
        if max_distance:
            raise TypeError(f"{caller}() got max_distance= and max_search_distance= (the same option): give one")
        max_distance = value
    if "smoothing_iterations" in keys:
        value = options.pop(keys["smoothing_iterations"])
        if not isinstance(value, (numbers.Integral, np.integer)) or isinstance(value, bool) or value < 0:
            raise ValueError(f"smoothing_iterations={value!r} is not a whole number >= 0")
    return max_distance


def check_progress(progress: Any) -> None:
    if progress is not None and not callable(progress):
        raise TypeError(f"progress must be callable or None, not {type(progress).__name__}")


def is_dataarray(obj: Any) -> bool:
    """Whether obj is an xarray.DataArray (without importing xarray)."""
    return any(c.__module__.startswith("xarray.") and c.__name__ == "DataArray" for c in type(obj).__mro__)
