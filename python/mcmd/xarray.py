"""mcmd for xarray: ``mcmd.xarray.fill(da)`` and the accessor ``da.mcmd.fill()``.

Importing this module registers the accessor ``.mcmd`` on every
``xarray.DataArray`` (as importing rioxarray registers ``.rio``)::

    import rioxarray, mcmd.xarray
    dem = rioxarray.open_rasterio("dem.tif")           # (band, y, x)
    filled = dem.mcmd.fill(rs="auto", seed=1)          # a DataArray: coords, CRS, nodata kept
    filled.rio.to_raster("dem_filled.tif")

A DataArray backed by numpy is filled now (:func:`mcmd.fill`); one backed by
dask stays lazy (:func:`mcmd.dask.fill`). Its last two dimensions are the
rows and columns; a third before them (rioxarray's ``band``) is filled band
by band. The nodata value is ``nodata=`` or the DataArray's own: the
``_FillValue`` attribute (rioxarray's ``rio.nodata``), or ``_FillValue`` in
its encoding while the values are still encoded. The result keeps the
coordinates (and so rioxarray's CRS and transform), attributes, encoding and
name; its values have the input's dtype.
"""
from __future__ import annotations

import math
from typing import Any

import numpy as np
import xarray

__all__ = ["fill", "FillAccessor"]


def fill(da: xarray.DataArray, mask: Any = None, nodata: Any = None, **options: Any) -> xarray.DataArray:
    """Fill the voids of a DataArray: now for numpy-backed data, lazily for
    dask-backed data. Options as for :func:`mcmd.fill`."""
    if not isinstance(da, xarray.DataArray):
        raise TypeError(f"mcmd.xarray.fill expects an xarray.DataArray, not {type(da).__name__}")
    if da.chunks is not None:
        from . import dask as mdask
        return mdask.fill(da, mask, nodata, **options)
    return fill_now(da, mask, nodata, **options)


def fill_now(da: xarray.DataArray, mask: Any = None, nodata: Any = None, **options: Any) -> xarray.DataArray:
    """:func:`mcmd.fill` on the DataArray's values (computed if lazy)."""
    from ._fill import fill as fill_array
    check_dims(da)
    if nodata is None:
        nodata = nodata_of(da)
    filled = fill_array(da.values, values_of(mask), nodata, **options)
    return da.copy(data=filled)


def check_dims(da: xarray.DataArray) -> None:
    if da.ndim not in (2, 3):
        raise ValueError(f"expected a DataArray of 2 dimensions (y, x) or 3 (band, y, x), got {da.dims}")


def values_of(mask: Any) -> Any:
    return mask.values if isinstance(mask, xarray.DataArray) else mask


def nodata_of(da: xarray.DataArray) -> Any:
    """The DataArray's nodata value as rioxarray keeps it, or None."""
    value = da.attrs.get("_FillValue")
    if value is None and "_FillValue" in da.encoding and np.dtype(da.encoding.get("dtype", da.dtype)) == da.dtype:
        value = da.encoding["_FillValue"]  # still encoded: the values hold it
    if value is None or (isinstance(value, (float, np.floating)) and math.isnan(value)):
        return None  # NaN cells are voids anyway
    return value.item() if isinstance(value, np.generic) else value


@xarray.register_dataarray_accessor("mcmd")
class FillAccessor:
    """``da.mcmd``: mcmd's fill as a method of DataArrays."""

    def __init__(self, da: xarray.DataArray) -> None:
        self._da = da

    def fill(self, mask: Any = None, nodata: Any = None, **options: Any) -> xarray.DataArray:
        """:func:`mcmd.xarray.fill` of this DataArray (lazy when it is dask-backed)."""
        return fill(self._da, mask, nodata, **options)
