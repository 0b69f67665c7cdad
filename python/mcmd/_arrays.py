"""Checks and conversions of the arrays mcmd.fill is given.

The raster becomes a C-contiguous array of one of GDAL's numeric types in
native byte order, the mask a uint8 array (0 = void), the nodata value a
number the band holds exactly: what the extension module takes. float16,
which GDAL does not store, is filled as float32 and rounded back.
"""
from __future__ import annotations

import math
import numbers
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
FLOAT16 = np.dtype("float16")


def raster(array: Any, dims: tuple = (2,)) -> np.ndarray:
    """`array` as an ndarray of a supported dtype with one of `dims` dimensions
    (not copied). ValueError otherwise."""
    data = np.asarray(array)
    if data.ndim not in dims:
        shapes = " or ".join({2: "2-D (rows, columns)", 3: "3-D (bands, rows, columns)"}[d] for d in dims)
        raise ValueError(f"expected a {shapes} array, got {data.ndim}-D of shape {data.shape}")
    if data.size == 0:
        raise ValueError(f"the array is empty (shape {data.shape})")
    check_dtype(data.dtype)
    return data


def check_dtype(dtype: np.dtype) -> None:
    """ValueError for a dtype mcmd cannot fill."""
    if dtype.kind == "b":
        raise ValueError("array dtype bool is not supported: a bool array is a mask, not a raster "
                         "(pass it as mask=, True = valid)")
    if dtype.newbyteorder("=") != FLOAT16:
        gdal_type(dtype)


def gdal_type(dtype: np.dtype) -> str:
    """The GDAL type name the fill works in for `dtype` (any byte order;
    float16 works in Float32). ValueError for others."""
    native = dtype.newbyteorder("=")
    if native == FLOAT16:
        return "Float32"
    name = GDAL_TYPES.get(native)
    if name is None:
        supported = ", ".join(str(t) for t in [*GDAL_TYPES, FLOAT16])
        raise ValueError(f"array dtype {dtype} is not supported: expected one of {supported} "
                         f"(GDAL's numeric types, and float16; complex numbers are not)")
    return name


def work_dtype(dtype: np.dtype) -> np.dtype:
    """The native dtype the fill runs in (float16: float32)."""
    native = dtype.newbyteorder("=")
    return np.dtype(np.float32) if native == FLOAT16 else native


def native_copy(data: np.ndarray) -> np.ndarray:
    """A new C-contiguous copy of `data` in the dtype the fill runs in."""
    return np.array(data, dtype=work_dtype(data.dtype), order="C", copy=True)


def valid_mask(mask: Any, data: np.ndarray, array: Any) -> np.ndarray | None:
    """The validity mask as uint8 (1 = valid, 0 = void) of `data`'s shape, a
    new array: `mask` (true / non-zero = valid; a 2-D mask applies to every
    band of a 3-D array) and, for a numpy masked array, its own mask."""
    masks = []
    if mask is not None:
        m = np.asarray(mask)
        if m.shape != data.shape and not (data.ndim == 3 and m.shape == data.shape[1:]):
            raise ValueError(f"the mask has shape {m.shape} but the array has shape {data.shape}")
        if m.dtype.kind not in "biuf":
            raise ValueError(f"mask dtype {m.dtype} is not supported: expected bool or a number (0 = void)")
        masks.append(np.broadcast_to(m != 0, data.shape))
    if isinstance(array, np.ma.MaskedArray) and np.ma.getmask(array) is not np.ma.nomask:
        masks.append(~np.ma.getmaskarray(array))
    if not masks:
        return None
    valid = masks[0] if len(masks) == 1 else np.logical_and(*masks)
    return np.ascontiguousarray(valid, dtype=np.uint8)


def nodata_value(nodata: Any, dtype: np.dtype) -> int | float | None:
    """The nodata value as the band takes it: an int for integer arrays, a
    float for float ones. ValueError when `dtype` cannot hold it exactly (an
    integer array's nodata is an integer of its range; float16's a float16)."""
    if nodata is None:
        return None
    if isinstance(nodata, (str, bytes)) or not isinstance(nodata, (numbers.Real, np.generic)):
        raise ValueError(f"nodata={nodata!r} is not a number")
    native = dtype.newbyteorder("=")
    if native.kind in "iu":
        info = np.iinfo(native)
        value = float(nodata) if not isinstance(nodata, (numbers.Integral, np.integer)) else int(nodata)
        exact = isinstance(value, int) or (math.isfinite(value) and value.is_integer())
        if not exact or not info.min <= int(value) <= info.max:
            raise ValueError(f"nodata={nodata!r} is not an integer in {native}'s range [{info.min}, {info.max}]: "
                             f"the array cannot hold it")
        return int(value)
    value = float(nodata)
    if native == FLOAT16 and math.isfinite(value) and float(np.float16(value)) != value:
        raise ValueError(f"nodata={nodata!r} is not a float16 value (the nearest is {float(np.float16(value))!r})")
    if native == np.float32 and math.isfinite(value) and abs(value) > float(np.finfo(np.float32).max):
        raise ValueError(f"nodata={nodata!r} is beyond float32's range: the array cannot hold it")
    return value


def band_nodata(nodata: Any, bands: int) -> list:
    """One nodata value per band: a number (or None) for all, or a sequence
    of `bands` of them (rasterio's ``nodatavals``)."""
    if nodata is None or isinstance(nodata, (numbers.Number, np.generic, str, bytes)):
        return [nodata] * bands
    values = list(nodata)
    if len(values) != bands:
        raise ValueError(f"nodata has {len(values)} values for {bands} bands")
    return values


def has_nonfinite(data: np.ndarray) -> bool:
    """Whether a cell is NaN or infinite (always a void of a float band)."""
    return data.dtype.kind == "f" and not bool(np.isfinite(data).all())


def voids(data: np.ndarray, valid: np.ndarray | None, nodata: int | float | None) -> np.ndarray:
    """The void cells of a band as the fill sees them (bool)."""
    void = np.zeros(data.shape, dtype=bool) if valid is None else valid == 0
    if data.dtype.kind == "f":
        void |= ~np.isfinite(data)
    if nodata is not None and not (isinstance(nodata, float) and math.isnan(nodata)):
        void |= data == np.asarray(nodata, dtype=data.dtype)
    return void


def to_dtype(work: np.ndarray, dtype: np.dtype, nodata: float | None) -> np.ndarray:
    """The filled band in `dtype`: `work` itself unless dtype is float16, whose
    values are rounded to nearest, clamped to its finite range like an integer
    band's, and filled cells kept off `nodata` (one step away) as the CLI
    keeps them. (Known and unfilled cells are float16 values: only a filled
    cell, never nodata in float32, can round onto it.)"""
    if dtype.newbyteorder("=") != FLOAT16:
        return work if work.dtype == dtype else work.astype(dtype)
    top = float(np.finfo(np.float16).max)
    finite = np.isfinite(work)
    out = np.where(finite, np.clip(work, -top, top), work).astype(FLOAT16)
    if nodata is not None and math.isfinite(nodata):
        hit = (out == np.float16(nodata)) & (work != nodata)
        if hit.any():  # a filled value that rounds onto nodata: the next float16 toward the fill
            away = np.where(work[hit] >= nodata, np.float16(np.inf), np.float16(-np.inf))
            out[hit] = np.nextafter(out[hit], away)
    return out.astype(dtype, copy=False)
