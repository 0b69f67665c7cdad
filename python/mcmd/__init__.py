"""mcmd: fill the nodata voids of rasters (DEMs first) from Python.

The same fill as the command-line tool ``mcmd_fillnodata`` (same options,
same results to the last bit):

``fill(array, mask=None, nodata=None, **options)``
    Fill a numpy array (rows, columns) or (bands, rows, columns), a numpy
    masked array or an xarray.DataArray; return a new one of the same kind
    and dtype. Valid cells are copied bit for bit.

``fill_file(src, dst=None, **options)``
    Fill a raster file into ``dst`` (or in place), exactly as
    ``mcmd_fillnodata src dst`` does.

``mcmd.dask.fill``
    The lazy fill of dask arrays and DataArrays of any size, on any Dask
    scheduler (imported on first use).

``mcmd.xarray``
    ``mcmd.xarray.fill(da)`` and the accessor ``da.mcmd.fill()`` (registered
    when ``mcmd.xarray`` is imported): lazy for dask-backed DataArrays.

Options are the library's NAME=VALUE options, given as keyword arguments in
any case (``rs="auto"``, ``method="paper-ds"``, ``tiling="ALWAYS"``,
``tile_size=257``, ``I=0.3``): METHOD, DELTA, I, I_BU, RIDGE_I, RIDGE_I_BU,
RIVER_I, RIVER_I_BU, H, RT, RS, SEED, MORPH, MORPH_CHANNEL, MAX_DISTANCE,
INNER_ONLY (``inner_only=True``: leave the voids touching the border),
MAX_VOID (``max_void=5000``: leave voids of more cells), FILL_FROM, TILE_SIZE,
TILING, NUM_THREADS (``threads=``). They are checked by the same parser as
the CLI's options: a bad value raises ValueError with the CLI's message.

Errors: ValueError for bad arguments and options, :class:`mcmd.Error` (a
RuntimeError) when a fill fails (unreadable file, no valid cell, I/O), and
:class:`mcmd.Cancelled` (an Error) when a progress callback stops it. The GIL
is released while a fill runs; Ctrl-C stops it cleanly (KeyboardInterrupt).
"""
import os as _os

# Passive OpenMP workers (they sleep as soon as they have no work), as the
# CLIs default to: libgomp's spinning between the fill's short parallel
# regions cost small fills 1.5-2.6x the CPU time on a busy machine. libgomp
# reads this once, when it is loaded: it takes effect only if nothing loaded
# libgomp before this import (numpy, GDAL and Dask do not), and a value the
# user set (or a GOMP_SPINCOUNT) wins. docs/python.md, "threads".
if "GOMP_SPINCOUNT" not in _os.environ:
    _os.environ.setdefault("OMP_WAIT_POLICY", "PASSIVE")
del _os

from ._file import fill_file  # noqa: E402  (the extension loads libgomp)
from ._fill import fill
from ._mcmd import Cancelled, Error
from ._mcmd import __version__  # the library's MCMDVersion()

__all__ = ["fill", "fill_file", "Error", "Cancelled", "__version__"]
_SUBMODULES = ("dask", "xarray")  # imported on first use: Dask and xarray are optional


def __getattr__(name: str):
    if name in _SUBMODULES:
        import importlib
        return importlib.import_module(f"{__name__}.{name}")
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


def __dir__() -> list:
    return sorted(__all__ + list(_SUBMODULES))

for _f in (fill, fill_file):
    _f.__module__ = __name__  # shown as mcmd.fill in help() and tracebacks
del _f
