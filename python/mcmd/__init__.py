"""mcmd: fill the nodata voids of rasters (DEMs first) from Python.

Two functions, the same fill as the command-line tool ``mcmd_fillnodata``
(same options, same results to the last bit):

``fill(array, mask=None, nodata=None, **options)``
    Fill a 2-D numpy array (any of GDAL's numeric types) and return a new
    array of the same dtype; valid cells are copied bit for bit.

``fill_file(src, dst=None, **options)``
    Fill a raster file into ``dst`` (or in place), exactly as
    ``mcmd_fillnodata src dst`` does: every band, georeferencing kept, the
    output written under a temporary name and renamed at the end.

Options are the library's NAME=VALUE options, given as keyword arguments in
any case (``rs="auto"``, ``method="paper-ds"``, ``tiling="ALWAYS"``,
``tile_size=257``, ``I=0.3``): METHOD, DELTA, I, I_BU, RIDGE_I, RIDGE_I_BU,
RIVER_I, RIVER_I_BU, H, RT, RS, SEED, MAX_DISTANCE, INNER_ONLY
(``inner_only=True``: leave the voids touching the border), MAX_VOID
(``max_void=5000``: leave voids of more cells), TILE_SIZE, TILING,
NUM_THREADS (``threads=``). They are checked by the same parser as the CLI's
options: a bad value raises ValueError with the CLI's message.

Errors: ValueError for bad arguments and options, :class:`mcmd.Error` (a
RuntimeError) when a fill fails (unreadable file, no valid cell, I/O), and
:class:`mcmd.Cancelled` (an Error) when a progress callback stops it. The GIL
is released while a fill runs; Ctrl-C stops it cleanly (KeyboardInterrupt).
"""
from __future__ import annotations

import os
from typing import Any, Callable, Iterable, Mapping, Optional

import numpy as np

from . import _arrays, _options
from ._mcmd import Cancelled, Error
from ._mcmd import __version__  # the library's MCMDVersion()
from ._mcmd import fill_array as _fill_array
from ._mcmd import fill_file as _fill_file

__all__ = ["fill", "fill_file", "Error", "Cancelled", "__version__"]

Progress = Callable[[float], Optional[bool]]


def fill(array: Any, mask: Any = None, nodata: int | float | None = None, *, method: str = "mcmd",
         rs: float | str = 0.0, seed: int = 0, max_distance: float = 0, threads: int | None = None,
         progress: Progress | None = None, **options: Any) -> np.ndarray:
    """Fill the voids of a 2-D array; return a new array of the same dtype.

    Parameters
    ----------
    array : array_like, 2-D (rows, columns)
        uint8, int8, uint16, int16, uint32, int32, uint64, int64, float32 or
        float64. Not modified. A numpy masked array's masked cells are voids.
    mask : array_like of bool or numbers, same shape, optional
        Validity mask as in rasterio's ``fillnodata``: true / non-zero =
        valid, false / 0 = void (like the CLI's ``-mask`` file).
    nodata : number, optional
        Cells equal to it are voids, and no filled cell is given this value.
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
        are (0 = fill every void).
    threads : int, optional
        Worker threads (default: all CPUs). The result does not depend on it.
    progress : callable(fraction) -> bool | None, optional
        Called from the calling thread with the fraction done (at most about
        ten times a second, and at the end); returning False cancels.
    **options
        Any other library option by name, in any case (``tiling="ALWAYS"``,
        ``tile_size=257``, ``H=0.6``, ``I=0.3``, ``delta="paper"``...).

    Voids are NaN and infinite cells (float arrays), cells equal to
    ``nodata`` and cells where ``mask`` is false. Integer results are rounded
    and clamped to the dtype exactly as the CLI writes them.

    Raises
    ------
    ValueError
        Not a 2-D array of a supported dtype, a mask of another shape, nothing
        marking the voids, a bad option (the CLI's message).
    mcmd.Error
        No valid cell to fill from.
    mcmd.Cancelled
        ``progress`` returned False.
    """
    data = _arrays.raster(array)
    gdal_type = _arrays.gdal_type(data.dtype)
    valid = _arrays.valid_mask(mask, data, array)
    nd = _arrays.nodata_value(nodata, data.dtype)
    if valid is None and nd is None and not _arrays.has_nonfinite(data):
        raise ValueError("the array has no nodata value, mask or NaN cell: nothing marks the voids "
                         "(pass nodata= or mask=)")
    named = {"METHOD": ("method", method), "RS": ("rs", rs), "SEED": ("seed", seed),
             "MAX_DISTANCE": ("max_distance", max_distance), "NUM_THREADS": ("threads", threads)}
    opts = _options.fill_options(options, named, caller="fill")
    _check_progress(progress)
    out = _arrays.native_copy(data)
    _fill_array(out, valid, gdal_type, nd, opts, progress)
    return out if out.dtype == data.dtype else out.astype(data.dtype)


def fill_file(src: str | os.PathLike[str], dst: str | os.PathLike[str] | None = None, *,
              bands: int | Iterable[int] | None = None, mask: str | os.PathLike[str] | None = None,
              nomask: bool = False, format: str | None = None,
              creation_options: Mapping[str, Any] | Iterable[str] | None = None,
              progress: Progress | None = None, **options: Any) -> str:
    """Fill the voids of a raster file, as ``mcmd_fillnodata src [dst]`` does.

    This runs the command-line tool's own code in this process: the results,
    files and messages are the CLI's.

    Parameters
    ----------
    src : path
        Any raster GDAL reads.
    dst : path, optional
        Output file; None fills ``src`` in place. Written under a temporary
        name in its folder and renamed at the end: a failed or cancelled fill
        leaves no partial file.
    bands : int or iterable of int, optional
        Bands to fill (1-based, like ``-b``); default: every band but alpha
        bands. The other bands are copied unchanged.
    mask : path, optional
        Validity raster of the same size (0 = void), like ``-mask``.
    nomask : bool
        Ignore the bands' own nodata value, mask and alpha band (``-nomask``).
    format : str, optional
        GDAL output driver (``-of``); default: from dst's extension, else GTiff.
    creation_options : mapping or iterable of "NAME=VALUE", optional
        Driver creation options (``-co``), e.g. ``{"COMPRESS": "DEFLATE"}``.
    progress : callable(fraction) -> bool | None, optional
        As for :func:`fill`; returning False cancels.
    **options
        The library's options, as for :func:`fill` (``method=``, ``rs=``,
        ``seed=``, ``max_distance=``, ``threads=``, ``tiling=``...).

    Returns
    -------
    str
        The path of the filled raster (``dst``, or ``src`` in place).

    Raises
    ------
    ValueError
        A bad band number, option, format or creation option (the CLI's message).
    mcmd.Error
        The fill failed (unreadable file, nothing marks the voids, no valid
        cell, I/O), with the message the CLI prints.
    mcmd.Cancelled
        ``progress`` returned False; nothing is left behind.
    """
    src_path = _options.path(src, "src")
    dst_path = "" if dst is None else _options.path(dst, "dst")
    flags: list[str] = []
    for band in _options.band_list(bands):
        flags += ["-b", str(band)]
    if mask is not None:
        flags += ["-mask", _options.path(mask, "mask")]
    if nomask:
        flags.append("-nomask")
    if format is not None:
        flags += ["-of", str(format)]
    for co in _options.creation_option_list(creation_options):
        flags += ["-co", co]
    for option in _options.fill_options(options, caller="fill_file"):
        flags += ["-o", option]
    _check_progress(progress)
    _fill_file(flags, src_path, dst_path, progress)
    return dst_path or src_path


def _check_progress(progress: Any) -> None:
    if progress is not None and not callable(progress):
        raise TypeError(f"progress must be callable or None, not {type(progress).__name__}")
