"""mcmd.fill gives the CLI's results to the last bit, for every GDAL type."""
import os

import numpy as np
import pytest

import mcmd
from conftest import TESTDATA, TYPES, cli_fill, read, same_bits, terrain, typed_raster, write

# Python keywords -> the same fill asked of the CLI.
CONFIGS = {
    "default": ({}, []),
    "rs_auto": ({"rs": "auto", "seed": 3}, ["-rs", "auto", "-seed", "3"]),
    "paper_ds": ({"method": "paper-ds", "rs": 0.1}, ["-method", "paper-ds", "-rs", "0.1"]),
    "tiled": ({"tiling": "ALWAYS", "tile_size": 65, "threads": 2}, ["-o", "TILING=ALWAYS", "-tile", "65"]),
}


def cli_result(tmp_path, array, nodata, flags, mask=None):
    src = write(tmp_path / "src.tif", array, nodata)
    extra = ["-mask", write(tmp_path / "mask.tif", mask.astype(np.uint8))] if mask is not None else []
    cli_fill(*flags, *extra, src, tmp_path / "out.tif")
    return read(tmp_path / "out.tif")


@pytest.mark.parametrize("config", sorted(CONFIGS))
@pytest.mark.parametrize("dtype", ["uint8", "int16", "uint16", "int32", "float32", "float64", "int64"])
def test_nodata_matches_cli(tmp_path, dtype, config):
    a, nodata = typed_raster(dtype)
    kwargs, flags = CONFIGS[config]
    expected = cli_result(tmp_path, a, nodata, flags)
    got = mcmd.fill(a, nodata=nodata, **kwargs)
    assert same_bits(got, expected)
    assert (got != nodata).all()


@pytest.mark.parametrize("dtype", ["int8", "uint32", "uint64"])
def test_other_types_match_cli(tmp_path, dtype):
    a, nodata = typed_raster(dtype)
    assert same_bits(mcmd.fill(a, nodata=nodata, rs=0.2), cli_result(tmp_path, a, nodata, ["-rs", "0.2"]))


@pytest.mark.parametrize("dtype", ["float32", "float64"])
@pytest.mark.parametrize("config", ["default", "tiled"])
def test_nan_voids_match_cli(tmp_path, dtype, config):
    z, voids = terrain()
    a = z.astype(dtype)
    a[voids] = np.nan
    a[0, 0] = np.inf  # infinite cells are voids too
    kwargs, flags = CONFIGS[config]
    got = mcmd.fill(a, **kwargs)
    assert np.isfinite(got).all()
    assert same_bits(got, cli_result(tmp_path, a, None, flags))


def test_mask_matches_cli(tmp_path):
    # Voids from the mask only (the array has no nodata), as with -mask.
    z, voids = terrain()
    a = np.round(z).astype(np.int16)
    expected = cli_result(tmp_path, a, None, ["-rs", "auto"], mask=~voids)
    for mask in (~voids, (~voids).astype(np.uint8) * 255, (~voids).astype(np.float32)):
        assert same_bits(mcmd.fill(a, mask=mask, rs="auto"), expected)


def test_mask_and_nodata_combine_as_in_cli(tmp_path):
    a, nodata = typed_raster("float32")
    extra = np.zeros(a.shape, bool)
    extra[60:70, 20:40] = True  # more voids, from the mask
    expected = cli_result(tmp_path, a, nodata, [], mask=~extra)
    got = mcmd.fill(a, mask=~extra, nodata=nodata)
    assert same_bits(got, expected)
    assert not same_bits(got, mcmd.fill(a, nodata=nodata))


def test_valid_cells_keep_their_bits():
    z, voids = terrain()
    a = z.copy()
    a[5, 5], a[5, 6], a[5, 7] = -0.0, 5e-324, np.nextafter(a[5, 7], 0)  # odd values stay as they are
    a[voids] = np.nan
    got = mcmd.fill(a)
    assert got.view(np.uint64)[~voids].tobytes() == a.view(np.uint64)[~voids].tobytes()
    assert not np.isnan(got).any()


def test_input_untouched_and_layouts_accepted():
    a, nodata = typed_raster("int16")
    before = a.copy()
    expected = mcmd.fill(a, nodata=nodata)
    assert same_bits(a, before)
    assert same_bits(mcmd.fill(np.asfortranarray(a), nodata=nodata), expected)
    swapped = a.astype(a.dtype.newbyteorder(">"))
    got = mcmd.fill(swapped, nodata=nodata)
    assert got.dtype == swapped.dtype and np.array_equal(got, expected)
    wide = np.zeros((a.shape[0], 2 * a.shape[1]), a.dtype)
    wide[:, ::2] = a
    assert same_bits(mcmd.fill(wide[:, ::2], nodata=nodata), expected)  # a strided view
    from_list = mcmd.fill(a.tolist(), nodata=nodata)  # a nested list becomes an int64 array
    assert from_list.dtype == np.int64 and np.array_equal(from_list, expected)


def test_masked_array_voids():
    a, nodata = typed_raster("float32")
    masked = np.ma.masked_equal(a, nodata)
    assert same_bits(mcmd.fill(masked), mcmd.fill(a, nodata=nodata))


def test_thread_count_and_seed():
    a, nodata = typed_raster("float32")
    one = mcmd.fill(a, nodata=nodata, rs="auto", threads=1, tiling="always", tile_size=33)
    assert same_bits(one, mcmd.fill(a, nodata=nodata, rs="auto", threads=2, TILING="ALWAYS", TILE_SIZE=33))
    assert not same_bits(one, mcmd.fill(a, nodata=nodata, rs="auto", seed=1, threads=1, tiling="always",
                                        tile_size=33))


def test_max_distance_leaves_far_voids():
    a, nodata = typed_raster("int16")
    got = mcmd.fill(a, nodata=nodata, max_distance=2)
    assert (got == nodata).any() and (got == nodata).sum() < (a == nodata).sum()


def test_version_is_the_cli_s(cli):
    import subprocess
    out = subprocess.run([cli, "--version"], capture_output=True, text=True, check=True).stdout
    assert out.split()[1] == mcmd.__version__


def test_inner_only_and_max_void_match_cli(tmp_path):
    a = terrain()[0].astype(np.float32)
    a[:, :6] = np.nan                # touches the border: left alone by inner_only
    a[20:26, 30:36] = np.nan         # 36 cells
    a[40:42, 10:12] = np.nan         # 4 cells
    inner = mcmd.fill(a, inner_only=True)
    assert np.isnan(inner[:, :6]).all() and not np.isnan(inner[:, 6:]).any()
    assert same_bits(inner, cli_result(tmp_path, a, None, ["-inner"]))
    capped = mcmd.fill(a, max_void=36)
    assert np.isnan(capped[:, :6]).all() and not np.isnan(capped[:, 6:]).any()
    assert np.isnan(mcmd.fill(a, max_void=35)[20:26, 30:36]).all()
    with pytest.raises(ValueError, match="MAX_VOID=1.5"):
        mcmd.fill(a, max_void=1.5)


def test_fill_from_a_second_dem_of_the_array_s_shape(tmp_path):
    z, voids = terrain()
    a = z.astype(np.float32)
    a[voids] = np.nan
    coarse = write(tmp_path / "second.tif", (z + 3.0).astype(np.float32))  # same grid: used cell for cell
    got = mcmd.fill(a, fill_from=str(coarse))
    plain = mcmd.fill(a)
    assert not np.isnan(got).any()
    assert same_bits(got[~voids], a[~voids])
    assert np.abs(got[voids] - z[voids]).mean() < np.abs(plain[voids] - z[voids]).mean()
    small = write(tmp_path / "small.tif", z[:50, :50].astype(np.float32))
    with pytest.raises(mcmd.Error, match="sizes differ"):
        mcmd.fill(a, fill_from=str(small))


def test_masked_array_in_masked_array_out():
    # Voids only under the mask (no nodata): those max_distance leaves are
    # masked in the result, the filled ones are not, and nothing else changes.
    a, nodata = typed_raster("int16")
    voids = a == nodata
    a[voids] = 1200  # what lies under the mask: a valid-looking value
    masked = np.ma.MaskedArray(a, mask=voids)
    got = mcmd.fill(masked, max_distance=2)
    ref = mcmd.fill(np.where(voids, nodata, a).astype(np.int16), nodata=nodata, max_distance=2)
    left = ref == nodata
    assert isinstance(got, np.ma.MaskedArray) and left.any() and (voids & ~left).any()
    assert np.array_equal(np.ma.getmaskarray(got), left)
    assert same_bits(got.data[~left], ref[~left])
    assert (got.data[left] == 1200).all()  # no nodata given: the cells as they were
    with_nodata = mcmd.fill(masked, nodata=-999, max_distance=2)
    assert (with_nodata.data[left] == -999).all() and with_nodata.fill_value == -999
    assert not np.ma.getmaskarray(mcmd.fill(masked)).any()  # every void filled: nothing masked


def test_bands_rows_columns_as_rasterio_reads_them(tmp_path):
    rasterio = pytest.importorskip("rasterio")
    src = os.path.join(TESTDATA, "peaks_2band.tif")
    cli_fill("-rs", "auto", "-seed", "2", src, tmp_path / "cli.tif")
    with rasterio.open(src) as ds:
        bands, nodatas = ds.read(), ds.nodatavals
    got = mcmd.fill(bands, nodata=nodatas, rs="auto", seed=2)
    assert got.shape == bands.shape
    for b in (1, 2):
        assert same_bits(got[b - 1], read(tmp_path / "cli.tif", b))
    assert same_bits(mcmd.fill(bands, nodata=-32768, rs="auto", seed=2), got)


def test_rasterio_fillnodata_keywords(tmp_path):
    rasterio = pytest.importorskip("rasterio")
    src = os.path.join(TESTDATA, "peaks_2band.tif")
    cli_fill("-md", "6", "-b", "1", src, tmp_path / "cli.tif")
    with rasterio.open(src) as ds:
        image, mask = ds.read(1), ds.read_masks(1)  # rasterio.fill.fillnodata(image, mask, ...)'s arguments
    got = mcmd.fill(image, mask, max_search_distance=6, smoothing_iterations=0)
    assert same_bits(got, read(tmp_path / "cli.tif"))
    with pytest.raises(TypeError, match="max_search_distance"):
        mcmd.fill(image, mask, max_distance=3, max_search_distance=6)
    with pytest.raises(ValueError, match="smoothing_iterations"):
        mcmd.fill(image, mask, smoothing_iterations=-1)


def test_float16_is_filled_as_float32():
    z, voids = terrain()
    a = z.astype(np.float16)
    a[voids] = np.nan
    got = mcmd.fill(a, rs="auto")
    assert got.dtype == np.float16 and np.isfinite(got).all()
    assert same_bits(got[~voids], a[~voids])
    assert same_bits(got, mcmd.fill(a.astype(np.float32), rs="auto").astype(np.float16))
