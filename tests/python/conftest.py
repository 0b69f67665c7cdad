"""Shared helpers for the tests of the Python package mcmd.

Run by ctest (tests/python/CMakeLists.txt) as
    PYTHONPATH=<build>/python MCMD_FILLNODATA=<build>/bin/mcmd_fillnodata \\
    /usr/bin/python3 -m pytest tests/python -q
Everything is real: rasters are GeoTIFFs written with GDAL in pytest's tmp
folders, and the reference is the real mcmd_fillnodata.
"""
import os
import subprocess

import numpy as np
import pytest
from osgeo import gdal

gdal.UseExceptions()
gdal.SetConfigOption("GDAL_PAM_ENABLED", "NO")  # no .aux.xml side-cars

REPO = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
TESTDATA = os.path.join(REPO, "testdata")
CLI = os.environ.get("MCMD_FILLNODATA", os.path.join(REPO, "build", "bin", "mcmd_fillnodata"))
PREFIX = "mcmd_fillnodata: error: "

# dtype -> (elevation in metres -> values, nodata): every type holds the
# peaks terrain (about 428..928 m) at a resolution of its own.
TYPES = {
    "uint8": (lambda z: (z - 400) / 3, 255),
    "int8": (lambda z: (z - 700) / 3, -128),
    "int16": (lambda z: z, -32768),
    "uint16": (lambda z: z * 10, 0),
    "int32": (lambda z: z * 1000, -999999),
    "uint32": (lambda z: z * 1000, 0),
    "int64": (lambda z: z * 1000 + 2.0**40, -1),
    "uint64": (lambda z: z * 1000 + 2.0**40, 0),
    "float32": (lambda z: z, -9999.0),
    "float64": (lambda z: z * 1.001, -9999.0),
}


def read(path, band=1):
    """A band of a raster as a numpy array of its own type (int8 too)."""
    ds = gdal.Open(str(path))
    b = ds.GetRasterBand(band)
    a = b.ReadAsArray()
    if b.GetMetadataItem("PIXELTYPE", "IMAGE_STRUCTURE") == "SIGNEDBYTE":
        a = a.view(np.int8)
    return a


def write(path, array, nodata=None, georeferenced=True, **creation):
    """A one-band GeoTIFF of `array` (its dtype; int8 as GDAL 3.6 stores it)."""
    array = np.asarray(array)
    co = [f"{k}={v}" for k, v in creation.items()]
    if array.dtype == np.int8 and not hasattr(gdal, "GDT_Int8"):
        gdt, co, data = gdal.GDT_Byte, co + ["PIXELTYPE=SIGNEDBYTE"], array.view(np.uint8)
    else:
        from osgeo import gdal_array
        gdt, data = gdal_array.NumericTypeCodeToGDALTypeCode(array.dtype), array
    ds = gdal.GetDriverByName("GTiff").Create(str(path), array.shape[1], array.shape[0], 1, gdt, co)
    if georeferenced:
        ds.SetGeoTransform((350000.0, 30.0, 0.0, 4110000.0, 0.0, -30.0))
        ds.SetProjection(gdal.Open(os.path.join(TESTDATA, "peaks_int16_geo.tif")).GetProjection())
    band = ds.GetRasterBand(1)
    if nodata is not None:
        band.SetNoDataValue(nodata)
    band.WriteArray(data)
    ds = None
    return str(path)


def run_cli(*args):
    """Run the real mcmd_fillnodata; returns (exit code, stderr)."""
    p = subprocess.run([CLI, "-q", *map(str, args)], capture_output=True, text=True, timeout=120)
    return p.returncode, p.stderr


def cli_fill(*args):
    """Run the CLI, which must succeed."""
    code, err = run_cli(*args)
    assert code == 0, err
    return code


def cli_error(*args):
    """The CLI's error message (without its 'mcmd_fillnodata: error: ' prefix)."""
    code, err = run_cli(*args)
    assert code != 0 and err.startswith(PREFIX), err
    return err[len(PREFIX):].strip()


def terrain():
    """The peaks terrain (float64, metres) and its 'voids A' (True = void)."""
    z = read(os.path.join(TESTDATA, "peaks_truth_float32.tif")).astype(np.float64)
    voids = read(os.path.join(TESTDATA, "peaks_float32_utm.tif")) == -9999
    return z, voids


def typed_raster(dtype):
    """The terrain as `dtype` with its voids set to the type's nodata value."""
    to_values, nodata = TYPES[dtype]
    z, voids = terrain()
    a = np.round(to_values(z)).astype(dtype) if np.dtype(dtype).kind in "iu" else to_values(z).astype(dtype)
    a[voids] = nodata
    return a, nodata


def same_bits(a, b):
    return a.dtype == b.dtype and a.shape == b.shape and a.tobytes() == b.tobytes()


@pytest.fixture(scope="session")
def cli():
    assert os.access(CLI, os.X_OK), f"mcmd_fillnodata not found at {CLI}: set MCMD_FILLNODATA"
    return CLI
