"""mcmd.fill_file writes the CLI's files, byte for byte."""
import filecmp
import os
import shutil

import numpy as np
import pytest
from osgeo import gdal

import mcmd
from conftest import TESTDATA, cli_fill, read, typed_raster, write

SAMPLE = os.path.join(TESTDATA, "sample_dem.tif")


def both(tmp_path, src, flags, dst_name="out.tif", **kwargs):
    """Fill src with the CLI and with fill_file; returns the two outputs."""
    cli_out, py_out = tmp_path / ("cli_" + dst_name), tmp_path / ("py_" + dst_name)
    cli_fill(*flags, src, cli_out)
    assert mcmd.fill_file(src, py_out, **kwargs) == str(py_out)
    return cli_out, py_out


@pytest.mark.parametrize("flags, kwargs", [
    ([], {}),
    (["-rs", "auto", "-seed", "9"], {"rs": "auto", "seed": 9}),
    (["-method", "paper-te", "-I", "0.3"], {"method": "paper-te", "I": 0.3}),
    (["-o", "TILING=ALWAYS", "-tile", "33", "-threads", "2"], {"tiling": "ALWAYS", "tile_size": 33, "threads": 2}),
])
def test_same_file_as_cli(tmp_path, flags, kwargs):
    cli_out, py_out = both(tmp_path, SAMPLE, flags, **kwargs)
    assert filecmp.cmp(cli_out, py_out, shallow=False)


def test_keeps_georeferencing(tmp_path):
    _, py_out = both(tmp_path, SAMPLE, [])
    src, out = gdal.Open(SAMPLE), gdal.Open(str(py_out))
    assert out.GetGeoTransform() == src.GetGeoTransform()
    assert out.GetProjection() == src.GetProjection() and out.GetProjection()
    assert out.GetRasterBand(1).GetNoDataValue() == src.GetRasterBand(1).GetNoDataValue()
    assert out.GetRasterBand(1).DataType == src.GetRasterBand(1).DataType


def test_every_band_and_selected_bands(tmp_path):
    src = os.path.join(TESTDATA, "peaks_2band.tif")
    cli_out, py_out = both(tmp_path, src, [])
    assert filecmp.cmp(cli_out, py_out, shallow=False)
    assert (read(py_out, 2) != -32768).all()
    cli_out, py_out = both(tmp_path, src, ["-b", "2"], "b2.tif", bands=[2])
    assert filecmp.cmp(cli_out, py_out, shallow=False)
    assert (read(py_out, 1) == -32768).any() and (read(py_out, 2) != -32768).all()


def test_mask_file_and_nomask(tmp_path):
    src = os.path.join(TESTDATA, "peaks_nonodata.tif")
    mask = os.path.join(TESTDATA, "peaks_mask.tif")
    cli_out, py_out = both(tmp_path, src, ["-nomask", "-mask", mask], mask=mask, nomask=True)
    assert filecmp.cmp(cli_out, py_out, shallow=False)


def test_output_format_and_creation_options(tmp_path):
    a, nodata = typed_raster("float32")
    src = write(tmp_path / "f32.tif", a, nodata)
    cli_out, py_out = both(tmp_path, src, ["-of", "COG", "-co", "COMPRESS=DEFLATE", "-co", "PREDICTOR=YES"],
                           format="COG", creation_options={"COMPRESS": "DEFLATE", "PREDICTOR": True})
    assert filecmp.cmp(cli_out, py_out, shallow=False)
    assert gdal.Open(str(py_out)).GetMetadataItem("LAYOUT", "IMAGE_STRUCTURE") == "COG"


def test_in_place(tmp_path):
    a, nodata = typed_raster("int32")
    cli_file = write(tmp_path / "cli.tif", a, nodata)
    py_file = write(tmp_path / "py.tif", a, nodata)
    cli_fill(cli_file)
    assert mcmd.fill_file(py_file) == py_file
    assert filecmp.cmp(cli_file, py_file, shallow=False)
    assert (read(py_file) != nodata).all()


def test_same_cells_as_fill(tmp_path):
    a, nodata = typed_raster("uint16")
    src = write(tmp_path / "u16.tif", a, nodata)
    mcmd.fill_file(src, tmp_path / "out.tif", rs="auto")
    assert np.array_equal(read(tmp_path / "out.tif"), mcmd.fill(a, nodata=nodata, rs="auto"))


def test_path_like_names(tmp_path):
    shutil.copy(SAMPLE, tmp_path / "-dash.tif")  # a name the CLI's parser would take for a flag
    out = mcmd.fill_file(tmp_path / "-dash.tif", tmp_path / "-out.tif")
    assert out == str(tmp_path / "-out.tif") and os.path.exists(out)
