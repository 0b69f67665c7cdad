"""What the tasks of mcmd.dask's graph run, on the workers: the four steps of
the chunked fill (mcmd/chunked_fill.hpp in the core) on numpy blocks.

Every function is pure: a task that is run again (a worker lost, a retry)
returns the same bits. Each worker process builds the plan once from the
chunk summaries and keeps it while the fill runs.
"""
from __future__ import annotations

import threading
from collections import OrderedDict
from typing import Any, NamedTuple, Optional

import numpy as np

from .. import _arrays, _mcmd
from .._mcmd import Error


class Spec(NamedTuple):
    """What every task of one fill needs to know (small, picklable)."""
    width: int
    height: int
    dtype: str          # numpy dtype (its str) of the raster
    gdal_type: str      # its GDAL type name
    nodata: Any         # int, float or None
    options: list       # the library's NAME=VALUE options
    token: str          # names this fill's plan in a worker's cache


_PLANS: "OrderedDict[str, Any]" = OrderedDict()  # the plans of the last few fills (bands of one raster)
_PLANS_KEPT = 4
_PLANS_LOCK = threading.Lock()


class Window(NamedTuple):
    """Cells [x0, x0 + w) × [y0, y0 + h) of band `band` of the raster file
    `path`, read by the task that needs them (nothing read travels)."""
    path: str
    band: int
    x0: int
    y0: int
    w: int
    h: int


_SOURCES: "OrderedDict[tuple, tuple]" = OrderedDict()  # (path, token): (dataset, its lock), the last few
_SOURCES_KEPT = 4
_SOURCES_LOCK = threading.Lock()


def forget(tokens: list) -> None:
    """Drop the plans and open files of these fills (run on each worker when
    a fill is done)."""
    with _PLANS_LOCK:
        for token in tokens:
            _PLANS.pop(token, None)
    with _SOURCES_LOCK:
        for key in [k for k in _SOURCES if k[1] in tokens]:
            del _SOURCES[key]


def _source(window: Window, spec: Spec) -> tuple:
    """This process's open dataset of the window's file, and the lock its
    reads take. One dataset per process: its blocks, decoded once, serve
    the margins the chunks around also read (a dataset per read decoded
    each margin's blocks again: half as much again on the mosaic)."""
    from osgeo import gdal
    key = (window.path, spec.token)
    with _SOURCES_LOCK:
        source = _SOURCES.get(key)
        if source is None:
            source = (gdal.OpenEx(window.path, gdal.OF_RASTER | gdal.OF_READONLY | gdal.OF_VERBOSE_ERROR),
                      threading.Lock())
            _SOURCES[key] = source
            while len(_SOURCES) > _SOURCES_KEPT:
                _SOURCES.popitem(last=False)
        else:
            _SOURCES.move_to_end(key)
        return source


def read(window: Window, spec: Spec) -> tuple:
    """The window's cells in the raster's dtype and the band's own validity
    mask (its mask or alpha band, as the CLI reads them; None when the nodata
    value alone marks the voids)."""
    from osgeo import gdal
    ds, lock = _source(window, spec)
    with lock:  # a GDAL dataset serves one thread at a time
        b = ds.GetRasterBand(window.band)
        cells = b.ReadAsArray(window.x0, window.y0, window.w, window.h)
        if cells is None:
            raise Error(f"cannot read '{window.path}': {gdal.GetLastErrorMsg()}")
        flags = b.GetMaskFlags()
        mask = None
        if not flags & (gdal.GMF_ALL_VALID | gdal.GMF_NODATA):
            mask = b.GetMaskBand().ReadAsArray(window.x0, window.y0, window.w, window.h)
    cells = cells.view(np.dtype(spec.dtype)) if cells.dtype.itemsize == np.dtype(spec.dtype).itemsize else cells
    return cells, mask


def crop(read_block: tuple, origin, own) -> tuple:
    """The chunk `own` out of a block read with its margin at `origin`."""
    cells, mask = read_block
    x, y = own[0] - origin[0], own[1] - origin[1]
    rows, cols = slice(y, y + own[3]), slice(x, x + own[2])
    return cells[rows, cols], None if mask is None else mask[rows, cols]


def _block(block: Any, mask: Any, spec: Spec) -> tuple:
    """(cells, mask) of a block given as an array, as a Window to read, or
    as what `read` returned."""
    if isinstance(block, Window):
        block = read(block, spec)
    if not isinstance(block, tuple):
        return block, mask
    cells, own = block
    if own is None or mask is None:
        return cells, own if mask is None else mask
    return cells, (np.asarray(mask) != 0) & (own != 0)


def _cells(block: np.ndarray, spec: Spec) -> np.ndarray:
    """A C-contiguous, native-order copy of a block in the type the fill
    runs in (the MEM band reads it in place)."""
    return _arrays.native_copy(np.asarray(block, dtype=np.dtype(spec.dtype)))


def _cells_read(block: Any, spec: Spec) -> np.ndarray:
    """The block itself when the fill can read it in place (steps that only
    read it), else a copy as _cells makes."""
    if (type(block) is np.ndarray and block.flags.c_contiguous and block.flags.writeable
            and block.dtype == _arrays.work_dtype(np.dtype(spec.dtype)) and block.dtype.isnative):
        return block
    return _cells(block, spec)


def _valid(mask: Optional[np.ndarray], block: Any = None) -> Optional[np.ndarray]:
    """The validity of a block's cells: `mask` and a masked block's own mask."""
    valid = None if mask is None else np.asarray(mask) != 0
    if isinstance(block, np.ma.MaskedArray) and np.ma.getmask(block) is not np.ma.nomask:
        own = ~np.ma.getmaskarray(block)
        valid = own if valid is None else valid & own
    return None if valid is None else np.ascontiguousarray(valid, dtype=np.uint8)


def _result(out: np.ndarray, spec: Spec) -> np.ndarray:
    return _arrays.to_dtype(out, np.dtype(spec.dtype), spec.nodata)


def summarize(block, mask, spec: Spec, origin, own) -> dict:
    """Step 1: the chunk's void runs, known range and guide moments."""
    block, mask = _block(block, mask, spec)
    return _mcmd.summarize_chunk(_cells_read(block, spec), _valid(mask, block), spec.gdal_type, spec.nodata, spec.options,
                                 tuple(origin), (spec.width, spec.height), tuple(own))


def gather(*summaries: dict) -> list:
    """The summaries of every chunk, as one value every later task depends on."""
    if sum(s["known"] for s in summaries) == 0:
        raise Error("the raster has no valid cell: nothing to fill from")
    return list(summaries)


def plan(spec: Spec, summaries: list):
    """Step 2: this worker's plan for the fill (built once, then reused)."""
    with _PLANS_LOCK:
        p = _PLANS.get(spec.token)
        if p is None:
            p = _mcmd.ChunkedPlan(spec.width, spec.height, spec.gdal_type, spec.options, summaries)
            _PLANS[spec.token] = p
            while len(_PLANS) > _PLANS_KEPT:  # memory stays bounded
                _PLANS.popitem(last=False)
        else:
            _PLANS.move_to_end(spec.token)
        return p


def solve(summaries: list, block, mask, spec: Spec, origin, own) -> tuple:
    """Step 3: the windows and small voids the chunk owns, solved."""
    block, mask = _block(block, mask, spec)
    return _mcmd.solve_chunk(plan(spec, summaries), _cells_read(block, spec), _valid(mask, block), spec.gdal_type, spec.nodata,
                             tuple(origin), tuple(own))


def part(solution: tuple, other) -> tuple:
    """What a chunk's neighbour needs of its solution (run where it lies: only this crosses)."""
    return _mcmd.solution_part(solution, tuple(other))


def blend(summaries: list, block, mask, spec: Spec, own, *around: tuple) -> np.ndarray:
    """Step 4: the chunk's cells, filled from the solutions around it."""
    block, mask = _block(block, mask, spec)
    out = _cells(block, spec)
    _mcmd.blend_chunk(plan(spec, summaries), out, _valid(mask, block), spec.gdal_type, spec.nodata, tuple(own),
                      list(around))
    return _result(out, spec)


def whole(block, mask, spec: Spec) -> np.ndarray:
    """A raster the CLI fills whole (or of one tile): one task, mcmd.fill's code."""
    block, mask = _block(block, mask, spec)
    out = _cells(block, spec)
    _mcmd.fill_array(out, _valid(mask, block), spec.gdal_type, spec.nodata, spec.options, None)
    return _result(out, spec)
