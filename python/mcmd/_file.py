"""mcmd.fill_file: mcmd_fillnodata's own code run in this process."""
from __future__ import annotations

import os
from typing import Any, Iterable, Mapping

from . import _options
from ._fill import Progress, check_progress
from ._mcmd import fill_file as _fill_file


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
    check_progress(progress)
    _fill_file(flags, src_path, dst_path, progress)
    return dst_path or src_path
