"""xarray.DataArray in, DataArray out: mcmd.fill, mcmd.dask.fill, mcmd.xarray.fill
and the accessor da.mcmd.fill(), each the CLI's bits, coordinates, CRS, nodata
and attributes kept."""
import os

import numpy as np
import pytest

import mcmd
from conftest import TESTDATA, cli_fill, read, same_bits

rioxarray = pytest.importorskip("rioxarray")
SRC = os.path.join(TESTDATA, "peaks_2band.tif")  # (band, y, x): two Int16 bands, nodata -32768


@pytest.fixture(scope="module")
def cli_bands(tmp_path_factory):
    out = tmp_path_factory.mktemp("cli") / "cli.tif"
    cli_fill("-rs", "auto", "-seed", "4", "-o", "TILING=ALWAYS", "-tile", "33", SRC, out)
    return np.stack([read(out, 1), read(out, 2)])


def same_raster(filled, source):
    assert filled.dims == source.dims and filled.shape == source.shape and filled.dtype == source.dtype
    for name in source.coords:
        assert filled[name].equals(source[name]), name
    assert filled.rio.crs == source.rio.crs and filled.rio.transform() == source.rio.transform()
    assert filled.rio.nodata == source.rio.nodata == -32768
    assert filled.attrs == source.attrs and filled.name == source.name


OPTIONS = {"rs": "auto", "seed": 4, "tiling": "ALWAYS", "tile_size": 33}


def test_fill_and_accessor_keep_the_raster(cli_bands):
    import mcmd.xarray  # noqa: F401  (registers da.mcmd)
    dem = rioxarray.open_rasterio(SRC, mask_and_scale=False)
    for filled in (mcmd.fill(dem, **OPTIONS), dem.mcmd.fill(**OPTIONS), mcmd.xarray.fill(dem, **OPTIONS)):
        same_raster(filled, dem)
        assert isinstance(filled.data, np.ndarray) and same_bits(filled.values, cli_bands)
    one = mcmd.fill(dem.sel(band=2), **OPTIONS)  # a band (y, x)
    assert one.dims == ("y", "x") and same_bits(one.values, cli_bands[1])


def test_dask_backed_stays_lazy(cli_bands, tmp_path):
    import dask
    import mcmd.xarray  # noqa: F401
    dem = rioxarray.open_rasterio(SRC, chunks={"y": 64, "x": 64}, mask_and_scale=False)
    for filled in (mcmd.dask.fill(dem, **OPTIONS), dem.mcmd.fill(**OPTIONS)):
        assert filled.chunks is not None  # lazy
        same_raster(filled, dem)
        with dask.config.set(scheduler="threads"):
            assert same_bits(filled.values, cli_bands)
    filled.rio.to_raster(tmp_path / "filled.tif")  # written back with its CRS and nodata
    assert same_bits(read(tmp_path / "filled.tif", 2), cli_bands[1])


def test_masked_and_scaled_dataarray():
    # mask_and_scale=True: voids are NaN in float values; they come back filled.
    dem = rioxarray.open_rasterio(SRC, mask_and_scale=True)
    filled = mcmd.fill(dem)
    assert np.isnan(dem.values).any() and not np.isnan(filled.values).any()
    assert filled.rio.encoded_nodata == dem.rio.encoded_nodata
    assert same_bits(filled.values[~np.isnan(dem.values)], dem.values[~np.isnan(dem.values)])
