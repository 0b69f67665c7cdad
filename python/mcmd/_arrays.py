"""Checks and conversions of the arrays mcmd.fill is given.

The raster becomes a C-contiguous array of one of GDAL's numeric types in
native byte order, the mask a uint8 array (0 = void), the nodata value a
number the GDAL band can hold: what the extension module takes.
"""
from __future__ import annotations

from typing import Any

import numpy as np

# numpy dtype -> GDAL data type name: every numeric type GDAL stores.
GDAL_TYPES = {
    np.dtype(name): gdal
    for name, gdal in [
        ("uint8", "Byte"), ("int8", "Int8"), ("uint16", "UInt16"), ("int16", "Int16"),
        ("uint32", "UInt32"), ("int32", "Int32"), ("uint64", "UInt64"), ("int64", "Int64"),
        ("float32", "Float32"), ("float64", "Float64"),
    ]
}


def raster(array: Any) -> np.ndarray:
    """`array` as a 2-D ndarray of a supported dtype (not copied). ValueError otherwise."""
    data = np.asarray(array)
    if data.ndim != 2:
        raise ValueError(f"expected a 2-D array (rows, columns), got {data.ndim}-D of shape {data.shape}")
    if data.size == 0:
        raise ValueError(f"the array is empty (shape {data.shape})")
    gdal_type(data.dtype)
    return data


def gdal_type(dtype: np.dtype) -> str:
    """The GDAL type name of `dtype` (any byte order). ValueError for others."""
    name = GDAL_TYPES.get(dtype.newbyteorder("="))
    if name is None:
        supported = ", ".join(str(t) for t in GDAL_TYPES)
        raise ValueError(f"array dtype {dtype} is not supported: expected one of {supported} "
                         f"(GDAL's numeric types; complex numbers are not)")
    return name


def native_copy(data: np.ndarray) -> np.ndarray:
    """A new C-contiguous copy of `data` in native byte order."""
    return np.array(data, dtype=data.dtype.newbyteorder("="), order="C", copy=True)


def valid_mask(mask: Any, data: np.ndarray, array: Any) -> np.ndarray | None:
    """The validity mask as uint8 (1 = valid, 0 = void), a new array: `mask`
    (true / non-zero = valid) and, for a numpy masked array, its own mask."""
    masks = []
    if mask is not None:
        m = np.asarray(mask)
        if m.shape != data.shape:
            raise ValueError(f"the mask has shape {m.shape} but the array has shape {data.shape}")
        if m.dtype.kind not in "biuf":
            raise ValueError(f"mask dtype {m.dtype} is not supported: expected bool or a number (0 = void)")
        masks.append(m != 0)
    if isinstance(array, np.ma.MaskedArray) and np.ma.getmask(array) is not np.ma.nomask:
        masks.append(~np.ma.getmaskarray(array))
    if not masks:
        return None
    valid = masks[0] if len(masks) == 1 else np.logical_and(*masks)
    return np.ascontiguousarray(valid, dtype=np.uint8)


def nodata_value(nodata: Any, dtype: np.dtype) -> int | float | None:
    """The nodata value as the band takes it: an int for 64-bit integer
    arrays (exact), else a float. ValueError when it cannot be one."""
    if nodata is None:
        return None
    if dtype.kind in "iu" and dtype.itemsize == 8:
        info = np.iinfo(dtype)
        try:
            value = int(nodata)
            exact = value == nodata
        except (TypeError, ValueError, OverflowError):
            exact = False
        if not exact or not info.min <= value <= info.max:
            raise ValueError(f"nodata={nodata!r} is not an integer in {dtype}'s range [{info.min}, {info.max}]")
        return value
    try:
        return float(nodata)
    except (TypeError, ValueError) as e:
        raise ValueError(f"nodata={nodata!r} is not a number") from e


def has_nonfinite(data: np.ndarray) -> bool:
    """Whether a cell is NaN or infinite (always a void of a float band)."""
    return data.dtype.kind == "f" and not bool(np.isfinite(data).all())
