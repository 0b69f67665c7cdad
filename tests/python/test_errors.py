"""Bad input raises the right exception, with the CLI's message."""
import os

import numpy as np
import pytest

import mcmd
from conftest import TESTDATA, cli_error, typed_raster, write

SAMPLE = os.path.join(TESTDATA, "sample_dem.tif")


def test_exception_classes():
    assert issubclass(mcmd.Error, RuntimeError) and issubclass(mcmd.Cancelled, mcmd.Error)
    assert mcmd.Error.__module__ == "mcmd" and mcmd.Error.__doc__


@pytest.mark.parametrize("array", [np.zeros(5), np.zeros((2, 3, 4, 5)), np.float32(1)])
def test_not_2d_or_3d(array):
    with pytest.raises(ValueError, match=r"expected a 2-D \(rows, columns\) or 3-D \(bands, rows, columns\) array"):
        mcmd.fill(array, nodata=0)


@pytest.mark.parametrize("dtype", [np.complex64, np.complex128, np.bool_, "U3", object])
def test_unsupported_dtype(dtype):
    with pytest.raises(ValueError, match="is not supported"):
        mcmd.fill(np.zeros((4, 4), dtype), nodata=0)


def test_bool_is_refused_as_a_mask():
    with pytest.raises(ValueError, match="a bool array is a mask, not a raster"):
        mcmd.fill(np.ones((4, 4), bool), nodata=0)


@pytest.mark.parametrize("dtype, nodata", [
    ("int16", 1200.5), ("int16", 40000), ("int16", 1e10), ("int16", float("nan")), ("int16", float("inf")),
    ("uint8", -1), ("uint8", 256), ("uint16", -0.5), ("int64", 2**63), ("int64", 0.5),
])
def test_nodata_the_dtype_cannot_hold(dtype, nodata):
    a = np.full((30, 30), 1200, dtype)  # valid cells that a rounded nodata would take for voids
    a[10:14, 10:14] = 7
    with pytest.raises(ValueError, match=r"is not an integer in .*'s range .*: the array cannot hold it"):
        mcmd.fill(a, nodata=nodata)


def test_nodata_float16_and_float32_must_hold():
    with pytest.raises(ValueError, match="not a float16 value"):
        mcmd.fill(np.zeros((4, 4), np.float16), nodata=-9999)  # float16 holds -10000, not -9999
    with pytest.raises(ValueError, match="beyond float32's range"):
        mcmd.fill(np.zeros((4, 4), np.float32), nodata=1e39)


def test_empty_array():
    with pytest.raises(ValueError, match="empty"):
        mcmd.fill(np.zeros((0, 4)), nodata=0)


def test_all_void_is_the_cli_s_error(tmp_path):
    a = np.full((21, 33), -32768, np.int16)
    with pytest.raises(mcmd.Error, match="has no valid cell: nothing to fill from"):
        mcmd.fill(a, nodata=-32768)
    src = os.path.join(TESTDATA, "all_nodata.tif")
    with pytest.raises(mcmd.Error) as e:
        mcmd.fill_file(src, tmp_path / "out.tif")
    assert str(e.value) == cli_error(src, tmp_path / "cli.tif")
    assert os.listdir(tmp_path) == []


@pytest.mark.parametrize("dtype", ["int16", "float32"])
def test_nothing_marks_the_voids(tmp_path, dtype):
    with pytest.raises(ValueError, match="nothing marks the voids"):
        mcmd.fill(np.ones((8, 8), dtype))
    src = os.path.join(TESTDATA, "no_nodata.tif")
    with pytest.raises(mcmd.Error) as e:
        mcmd.fill_file(src, tmp_path / "out.tif")
    assert "nothing marks the voids" in str(e.value)
    assert str(e.value) == cli_error(src, tmp_path / "cli.tif")


@pytest.mark.parametrize("kwargs, flags", [
    ({"rs": 11}, ["-rs", "11"]),
    ({"rs": "rough"}, ["-rs", "rough"]),
    ({"method": "kriging"}, ["-method", "kriging"]),
    ({"seed": -1}, ["-seed", "-1"]),
    ({"threads": 0}, ["-threads", "0"]),
    ({"tile_size": 100}, ["-tile", "100"]),
    ({"tiling": "sometimes"}, ["-o", "TILING=sometimes"]),
    ({"H": 2}, ["-H", "2"]),
    ({"frobnicate": 1}, ["-o", "frobnicate=1"]),
])
def test_bad_option_has_the_cli_s_message(tmp_path, kwargs, flags):
    expected = cli_error(*flags, SAMPLE, tmp_path / "cli.tif")
    a, nodata = typed_raster("int16")
    with pytest.raises(ValueError) as e:
        mcmd.fill(a, nodata=nodata, **kwargs)
    assert str(e.value) == expected
    with pytest.raises(ValueError) as e:
        mcmd.fill_file(SAMPLE, tmp_path / "out.tif", **kwargs)
    assert str(e.value) == expected
    assert os.listdir(tmp_path) == []


def test_option_given_twice():
    a, nodata = typed_raster("int16")
    with pytest.raises(TypeError, match="option RS twice"):
        mcmd.fill(a, nodata=nodata, RS="auto")
    with pytest.raises(TypeError, match="option NUM_THREADS twice"):
        mcmd.fill_file(SAMPLE, "x.tif", threads=1, num_threads=2)


def test_bad_mask_and_nodata():
    a, nodata = typed_raster("int64")
    with pytest.raises(ValueError, match="the mask has shape"):
        mcmd.fill(a, mask=np.ones((3, 3), bool))
    assert (mcmd.fill(a, nodata=float(nodata)) != nodata).all()
    with pytest.raises(ValueError, match="is not a number"):
        mcmd.fill(a.astype(np.float32), nodata="none")


@pytest.mark.parametrize("kwargs, flags", [
    ({"bands": [3]}, ["-b", "3"]),
    ({"bands": 0}, ["-b", "0"]),
    ({"format": "NoSuchDriver"}, ["-of", "NoSuchDriver"]),
    ({"creation_options": ["COMPRESS"]}, ["-co", "COMPRESS"]),
    ({"creation_options": {"COMPRESS": "ZIPPY"}}, ["-co", "COMPRESS=ZIPPY"]),
    ({"mask": os.path.join(TESTDATA, "peaks_mask.tif")}, ["-mask", os.path.join(TESTDATA, "peaks_mask.tif")]),
])
def test_bad_file_arguments(tmp_path, kwargs, flags):
    expected = cli_error(*flags, SAMPLE, tmp_path / "cli.tif")
    with pytest.raises(ValueError) as e:
        mcmd.fill_file(SAMPLE, tmp_path / "out.tif", **kwargs)
    assert str(e.value) == expected
    assert os.listdir(tmp_path) == []


def test_unreadable_files(tmp_path):
    missing = tmp_path / "missing.tif"
    with pytest.raises(mcmd.Error) as e:
        mcmd.fill_file(missing, tmp_path / "out.tif")
    assert str(e.value) == cli_error(missing, tmp_path / "cli.tif")
    not_raster = tmp_path / "notes.txt"
    not_raster.write_text("not a raster\n")
    with pytest.raises(mcmd.Error) as e:
        mcmd.fill_file(not_raster, tmp_path / "out.tif")
    assert str(e.value) == cli_error(not_raster, tmp_path / "cli.tif")
    with pytest.raises(mcmd.Error, match="cannot write"):
        mcmd.fill_file(SAMPLE, tmp_path / "no_such_folder" / "out.tif")
    with pytest.raises(ValueError, match="empty file name"):
        mcmd.fill_file("", tmp_path / "out.tif")
    assert sorted(os.listdir(tmp_path)) == ["notes.txt"]
