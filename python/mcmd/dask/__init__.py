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

__all__ = ["fill"]


def fill(data: Any, mask: Any = None, nodata: Any = None, *, method: str = "mcmd", rs: float | str = 0.0,
         seed: int = 0, max_distance: float = 0, chunks: Optional[int] = None, **options: Any) -> Any:
    """Fill the voids of a dask array or xarray.DataArray, lazily.

    Parameters
    ----------
    data : dask.array.Array, xarray.DataArray or array_like
        (rows, columns), or (bands, rows, columns) filled band by band. Any
        dtype :func:`mcmd.fill` takes. A DataArray keeps its coordinates,
        attributes and rioxarray fields; its nodata value is its
        ``_FillValue`` (``rio.nodata``) unless given.
    mask : same shape, or (rows, columns) for every band, optional
        Validity mask, true / non-zero = valid (as :func:`mcmd.fill`).
    nodata : number or one per band, optional
        Cells equal to it are voids; the dtype must hold it exactly.
    method, rs, seed, max_distance, **options
        As for :func:`mcmd.fill` (``tile_size=``, ``tiling=``, ``H=``,
        ``inner_only=True``, ``max_void=5000`` in cells...). ``fill_from``,
        ``rivers``, ``ridges`` and ``morph="auto"`` need the whole raster at
        once: use :func:`mcmd.fill_file` or :func:`mcmd.fill` for them.
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
        Not 2-D or 3-D, an unsupported dtype, a mask of another shape, a
        nodata value the dtype cannot hold, nothing marking the voids of an
        integer raster, a bad or whole-raster option.
    mcmd.Error
        At compute time: no valid cell to fill from.
    """
    from ._lazy import fill as lazy_fill  # dask.array is imported on first use
    return lazy_fill(data, mask, nodata, method=method, rs=rs, seed=seed, max_distance=max_distance, chunks=chunks,
                     **options)
