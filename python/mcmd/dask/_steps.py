"""What the tasks of mcmd.dask's graph run, on the workers: the four steps of
the chunked fill (mcmd/chunked_fill.hpp in the core) on numpy blocks.

Every function is pure: a task that is run again (a worker lost, a retry)
returns the same bits. Each worker process builds the plan once from the
chunk summaries and keeps it while the fill runs.
"""
from __future__ import annotations

import threading
from typing import Any, NamedTuple, Optional

import numpy as np

from .. import _arrays, _mcmd
from .._mcmd import Error


class Spec(NamedTuple):
    """What every task of one fill needs to know (small, picklable)."""
    width: int
    height: int
    dtype: str          # numpy dtype name of the raster
    gdal_type: str      # its GDAL type name
    nodata: Any         # int, float or None
    options: list       # the library's NAME=VALUE options
    token: str          # names this fill's plan in a worker's cache


_PLANS: dict = {}
_PLANS_LOCK = threading.Lock()


def _cells(block: np.ndarray, spec: Spec) -> np.ndarray:
    """A C-contiguous, native-order copy of a block (the MEM band reads it in place)."""
    return _arrays.native_copy(np.asarray(block, dtype=np.dtype(spec.dtype)))


def _valid(mask: Optional[np.ndarray]) -> Optional[np.ndarray]:
    return None if mask is None else np.ascontiguousarray(np.asarray(mask) != 0, dtype=np.uint8)


def summarize(block, mask, spec: Spec, origin, own) -> dict:
    """Step 1: the chunk's void runs, known range and guide moments."""
    return _mcmd.summarize_chunk(_cells(block, spec), _valid(mask), spec.gdal_type, spec.nodata, spec.options,
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
            _PLANS.clear()  # one fill at a time per worker keeps memory bounded
            _PLANS[spec.token] = p
        return p


def solve(summaries: list, block, mask, spec: Spec, origin, own) -> tuple:
    """Step 3: the windows and small voids the chunk owns, solved."""
    return _mcmd.solve_chunk(plan(spec, summaries), _cells(block, spec), _valid(mask), spec.gdal_type, spec.nodata,
                             tuple(origin), tuple(own))


def part(solution: tuple, other) -> tuple:
    """What a chunk's neighbour needs of its solution (run where it lies: only this crosses)."""
    return _mcmd.solution_part(solution, tuple(other))


def blend(summaries: list, block, mask, spec: Spec, own, *around: tuple) -> np.ndarray:
    """Step 4: the chunk's cells, filled from the solutions around it."""
    out = _cells(block, spec)
    _mcmd.blend_chunk(plan(spec, summaries), out, _valid(mask), spec.gdal_type, spec.nodata, tuple(own),
                      list(around))
    return out.astype(np.dtype(spec.dtype), copy=False)


def whole(block, mask, spec: Spec) -> np.ndarray:
    """A raster the CLI fills whole (or of one tile): one task, mcmd.fill's code."""
    out = _cells(block, spec)
    _mcmd.fill_array(out, _valid(mask), spec.gdal_type, spec.nodata, spec.options, None)
    return out.astype(np.dtype(spec.dtype), copy=False)
