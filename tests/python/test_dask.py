"""mcmd.dask: the lazy fill of dask arrays and DataArrays, and the command
python3 -m mcmd.dask, against the real mcmd_fillnodata, bit for bit, on real
LocalClusters (worker processes) and the threaded scheduler."""
import os
import signal
import subprocess
import sys
import time
from contextlib import nullcontext

import cloudpickle
import dask
import dask.array as da
import numpy as np
import pytest
from distributed import Client, LocalCluster

import mcmd
import mcmd.dask
from conftest import cli_fill, read, same_bits, write

# This file's functions run on `dask worker` processes, which cannot import it.
cloudpickle.register_pickle_by_value(sys.modules[__name__])

H, W = 520, 610
TILE = ["-o", "TILE_SIZE=65", "-o", "TILING=ALWAYS"]


def raster(dtype="float32", nodata=-9999):
    """Terrain with a void spanning several chunks of 128, blobs and scattered cells."""
    y, x = np.mgrid[0:H, 0:W]
    z = 600 + 250 * np.sin(x * 0.019) * np.cos(y * 0.023) + 90 * np.sin(0.05 * x + 0.03 * y) + 0.4 * x
    void = (x - 300) ** 2 / 180.0 ** 2 + (y - 260) ** 2 / 120.0 ** 2 < 1
    void |= (x - 60) ** 2 + (y - 450) ** 2 < 25 ** 2
    void |= np.random.default_rng(3).random((H, W)) < 0.02
    a = z.astype(dtype)
    a[void] = nodata
    return a


def cli_result(tmp_path, a, nodata, *options):
    src = write(tmp_path / "src.tif", a, nodata)
    cli_fill(*TILE, *options, src, tmp_path / "cli.tif")
    return src, read(tmp_path / "cli.tif")


@pytest.mark.parametrize("dtype,nodata", [("float32", -9999), ("int16", -32768), ("uint16", 0)])
def test_equals_cli_for_two_chunkings(tmp_path, dtype, nodata):
    a = raster(dtype, nodata)
    _, want = cli_result(tmp_path, a, nodata)
    for chunks in (128, 200):
        with dask.config.set(scheduler="threads"):
            got = mcmd.dask.fill(da.from_array(a, chunks=chunks), nodata=nodata, tile_size=65,
                                 tiling="ALWAYS").compute()
        assert same_bits(got, want), f"chunks of {chunks}"


def test_rough_fill_with_max_distance_equals_cli(tmp_path):
    a = raster()
    _, want = cli_result(tmp_path, a, -9999, "-rs", "auto", "-seed", "5", "-md", "40")
    with dask.config.set(scheduler="threads"):
        got = mcmd.dask.fill(da.from_array(a, chunks=150), nodata=-9999, rs="auto", seed=5, max_distance=40,
                             tile_size=65, tiling="ALWAYS").compute()
    assert same_bits(got, want)


@pytest.mark.parametrize("options", [("-inner",), ("-maxvoid", "2000")])
def test_voids_left_unfilled_as_by_the_cli(tmp_path, options):
    a = raster()
    a[200:260, :40] = -9999  # a void on the border, which -inner leaves
    _, want = cli_result(tmp_path, a, -9999, *options)
    assert (want == -9999).any() and (want != a).any()
    kwargs = {"inner_only": True} if options[0] == "-inner" else {"max_void": 2000}
    got = mcmd.dask.fill(da.from_array(a, chunks=128), nodata=-9999, tile_size=65, tiling="ALWAYS",
                         **kwargs).compute(scheduler="threads")
    assert same_bits(got, want)


def test_small_raster_is_filled_whole_like_the_cli(tmp_path):
    a = raster()[:200, :300].copy()
    src = write(tmp_path / "small.tif", a, -9999)
    cli_fill(src, tmp_path / "small_cli.tif")  # the default: filled whole
    got = mcmd.dask.fill(da.from_array(a, chunks=64), nodata=-9999).compute(scheduler="threads")
    assert same_bits(got, read(tmp_path / "small_cli.tif"))


# Every wait on a cluster is bounded: a hang fails the test with a reason
# instead of stalling the suite until ctest's timeout.
WAIT = 240


def local_cluster(workers):
    return LocalCluster(n_workers=workers, threads_per_worker=1, processes=True, dashboard_address=None)


@pytest.fixture(scope="module")
def cluster():
    with local_cluster(2) as c:
        yield c


def test_local_clusters_of_two_and_one_workers(tmp_path, cluster):
    # Separate clusters rather than one scaled down: a computation started
    # while a worker retires can lose its results in this Dask.
    a = raster()
    _, want = cli_result(tmp_path, a, -9999)
    for workers, chunks in ((2, 128), (1, 256)):
        with (local_cluster(1) if workers == 1 else nullcontext(cluster)) as c, Client(c) as client:
            client.wait_for_workers(workers, timeout=WAIT)
            lazy = mcmd.dask.fill(da.from_array(a, chunks=chunks), nodata=-9999, tile_size=65, tiling="ALWAYS")
            got = client.compute(lazy).result(timeout=WAIT)
            assert same_bits(got, want), f"{workers} workers, chunks of {chunks}"


def test_a_killed_worker_is_retried_with_the_same_result(tmp_path, cluster):
    a = raster()
    _, want = cli_result(tmp_path, a, -9999)
    with Client(cluster) as client:
        client.wait_for_workers(2, timeout=WAIT)
        lazy = mcmd.dask.fill(da.from_array(a, chunks=128), nodata=-9999, tile_size=65, tiling="ALWAYS")
        future = client.compute(lazy)
        pids = client.run(os.getpid)
        # Kill one worker once it holds results (its share must be computed again).
        deadline = time.time() + 60
        while time.time() < deadline and not any(client.who_has().values()):
            time.sleep(0.05)
        os.kill(next(iter(pids.values())), signal.SIGKILL)
        got = future.result(timeout=WAIT)
        assert same_bits(got, want)


def test_dataarray_keeps_coordinates_and_nodata(tmp_path):
    rioxarray = pytest.importorskip("rioxarray")
    a = raster()
    src, want = cli_result(tmp_path, a, -9999)
    band = rioxarray.open_rasterio(src, chunks={"y": 128, "x": 128}, mask_and_scale=False).sel(band=1)
    filled = mcmd.dask.fill(band, tile_size=65, tiling="ALWAYS")  # nodata from band.rio.nodata
    assert filled.rio.crs == band.rio.crs and filled.rio.transform() == band.rio.transform()
    assert filled.rio.nodata == -9999 and (filled.x == band.x).all()
    assert same_bits(filled.compute(scheduler="threads").values, want)


def test_bad_input_raises():
    a = da.from_array(raster(), chunks=128)
    with pytest.raises(ValueError, match="2-D .* or 3-D"):
        mcmd.dask.fill(a[None, None], nodata=-9999)
    with pytest.raises(ValueError, match="complex"):
        mcmd.dask.fill(a.astype(np.complex64), nodata=-9999)
    with pytest.raises(ValueError, match="nothing marks the voids"):
        mcmd.dask.fill(a.astype(np.int32))
    with pytest.raises(ValueError, match="RS"):
        mcmd.dask.fill(a, nodata=-9999, rs="rough")
    with pytest.raises(ValueError, match="FILL_FROM"):
        mcmd.dask.fill(a, nodata=-9999, fill_from="other.tif")
    with pytest.raises(ValueError, match="MORPH=auto"):  # not silently ignored
        mcmd.dask.fill(a, nodata=-9999, morph="auto")
    with pytest.raises(ValueError, match="cannot hold it"):
        mcmd.dask.fill(a.astype(np.int16), nodata=1200.5)
    with pytest.raises(ValueError, match="in cells"):
        mcmd.dask.fill(a, nodata=-9999, max_void="3km2")
    with pytest.raises(ValueError, match="mask"):
        mcmd.dask.fill(a, mask=np.ones((3, 3), bool))
    empty = da.full((300, 400), -9999.0, chunks=128)
    with pytest.raises(mcmd.Error, match="no valid cell"):
        mcmd.dask.fill(empty, nodata=-9999, tiling="ALWAYS", tile_size=65).compute(scheduler="threads")


def run_module(*args):
    return subprocess.run([sys.executable, "-m", "mcmd.dask", *map(str, args)], capture_output=True, text=True,
                          timeout=240)


def test_module_writes_the_cli_s_geotiff_and_zarr(tmp_path):
    a = raster()
    src, want = cli_result(tmp_path, a, -9999)
    p = run_module(src, tmp_path / "threads.tif", "--chunk", "128", "-q", *TILE)  # the threaded scheduler
    assert p.returncode == 0, p.stderr
    assert same_bits(read(tmp_path / "threads.tif"), want)
    p = run_module(src, tmp_path / "dask.tif", "--workers", "2", "--chunk", "128", *TILE)
    assert p.returncode == 0, p.stderr
    assert "100% Completed" in p.stdout  # Dask's progress bar
    assert same_bits(read(tmp_path / "dask.tif"), want)
    from osgeo import gdal
    out, ref = gdal.Open(str(tmp_path / "dask.tif")), gdal.Open(src)
    assert out.GetGeoTransform() == ref.GetGeoTransform() and out.GetProjection() == ref.GetProjection()
    assert out.GetRasterBand(1).GetNoDataValue() == -9999
    p = run_module(src, tmp_path / "dask.zarr", "--workers", "1", "-q", *TILE)
    assert p.returncode == 0, p.stderr
    import xarray
    assert same_bits(xarray.open_zarr(tmp_path / "dask.zarr")["band_1"].values, want)
    assert not [f for f in os.listdir(tmp_path) if "mcmd-tmp" in f]


def test_module_local_cluster_neither_compresses_nor_trims(monkeypatch):
    # --workers N's cluster: no lz4 between processes of one machine,
    # glibc's own malloc tuning in its workers (no MALLOC_TRIM_THRESHOLD_,
    # which the Nanny sets by default and which also leaks into this
    # process's environment once any default LocalCluster has started), and
    # no stack sampling for a dashboard it does not have.
    monkeypatch.delenv("MALLOC_TRIM_THRESHOLD_", raising=False)
    from mcmd.dask._cluster import local_cluster as module_cluster
    with module_cluster(1) as c, Client(c) as client:
        client.wait_for_workers(1, timeout=WAIT)
        seen = client.run(lambda: (os.environ.get("MALLOC_TRIM_THRESHOLD_"),
                                   dask.config.get("distributed.comm.compression"),
                                   dask.config.get("distributed.worker.profile.enabled")))
    assert list(seen.values()) == [(None, None, False)]


def test_module_errors_are_one_line_and_leave_nothing(tmp_path):
    p = run_module(tmp_path / "missing.tif", tmp_path / "out.tif")
    assert p.returncode == 1 and p.stderr.startswith("mcmd.dask: cannot open") and p.stderr.count("\n") == 1
    src = write(tmp_path / "src.tif", raster(), -9999)
    p = run_module(src, tmp_path / "out.tif", "-b", "3")
    assert p.returncode == 1 and "band 3 does not exist" in p.stderr
    p = run_module(src, tmp_path / "out.tif", "-rs", "rough", "--workers", "1")
    assert p.returncode == 1 and p.stderr.startswith("mcmd.dask: ") and p.stderr.count("\n") == 1, p.stderr
    # Its messages name its own flags, not Python keywords.
    p = run_module(write(tmp_path / "no_nodata.tif", raster("int16", 0)), tmp_path / "out.tif")
    assert p.returncode == 1 and "gdal_edit.py -a_nodata" in p.stderr and "nodata=" not in p.stderr, p.stderr
    p = run_module(src, tmp_path / "out.tif", "-o", "MORPH=auto")
    assert p.returncode == 1 and "-morph auto needs the whole raster" in p.stderr, p.stderr
    assert not os.path.exists(tmp_path / "out.tif")
    assert not [f for f in os.listdir(tmp_path) if "mcmd-tmp" in f]


def test_module_void_cap_as_an_area_is_the_cli_s(tmp_path):
    from osgeo import gdal, osr
    src = write(tmp_path / "utm.tif", raster(), -9999)
    utm = osr.SpatialReference()
    utm.ImportFromEPSG(32611)
    ds = gdal.Open(src, gdal.GA_Update)
    ds.SetProjection(utm.ExportToWkt())  # 30 m cells in metres
    ds = None
    cli_fill(*TILE, "-maxvoid", "1.5km2", src, tmp_path / "cli.tif")  # 1666 cells
    want = read(tmp_path / "cli.tif")
    p = run_module(src, tmp_path / "capped.tif", "--workers", "1", "-q", "-maxvoid", "1.5km2", *TILE)
    assert p.returncode == 0, p.stderr
    assert same_bits(read(tmp_path / "capped.tif"), want) and (want == -9999).any()


def test_module_keeps_band_descriptions_and_metadata(tmp_path):
    from osgeo import gdal
    from conftest import TESTDATA
    src = os.path.join(TESTDATA, "peaks_2band.tif")
    cli_fill(src, tmp_path / "cli.tif")
    p = run_module(src, tmp_path / "dask.tif", "-q")
    assert p.returncode == 0, p.stderr
    cli, out = gdal.Open(str(tmp_path / "cli.tif")), gdal.Open(str(tmp_path / "dask.tif"))
    for b in (1, 2):
        cb, ob = cli.GetRasterBand(b), out.GetRasterBand(b)
        assert ob.GetDescription() == cb.GetDescription() != ""
        assert ob.GetColorInterpretation() == cb.GetColorInterpretation()
        assert same_bits(ob.ReadAsArray(), cb.ReadAsArray())


def test_docs_example_runs_on_a_distributed_client(tmp_path, cluster):
    """docs/dask.md's example, as written, on a LocalCluster (its scheduler
    address and a raster of ours put in place of the example's)."""
    import re
    from conftest import REPO
    with open(os.path.join(REPO, "docs", "dask.md"), encoding="utf-8") as f:
        example = re.search(r"```python\n(.*?)```", f.read(), re.S).group(1)
    src, want = cli_result(tmp_path, raster(), -9999)
    code = (example.replace("tcp://scheduler:8786", cluster.scheduler_address).replace("mosaic.vrt", src)
            .replace('"filled.tif"', repr(str(tmp_path / "filled.tif"))).replace("rs=\"auto\", seed=1", "tile_size=65, tiling=\"ALWAYS\""))
    assert cluster.scheduler_address in code and src in code
    scope = {}
    exec(compile(code, "docs/dask.md", "exec"), scope)
    scope["client"].close()
    assert same_bits(read(tmp_path / "filled.tif"), want)


def held_by_the_steps():
    """On a worker: the files kept open and the plans kept by mcmd.dask's tasks."""
    steps = sys.modules.get("mcmd.dask._steps")
    return [] if steps is None else [*steps._SOURCES, *steps._PLANS]


def test_a_cluster_of_dask_scheduler_and_dask_worker_processes(tmp_path):
    """A real multi-process cluster: `dask scheduler` and two `dask worker`
    processes on localhost, used by python3 -m mcmd.dask and by a Client."""
    a = raster()
    src, want = cli_result(tmp_path, a, -9999)
    address_file = tmp_path / "scheduler.json"
    common = ["--no-dashboard"]
    procs = [subprocess.Popen(["dask", "scheduler", "--host", "127.0.0.1", "--port", "0", "--scheduler-file",
                               str(address_file), *common], stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)]
    try:
        deadline = time.time() + WAIT
        while not address_file.exists() and time.time() < deadline:
            time.sleep(0.1)
        for _ in range(2):
            procs.append(subprocess.Popen(["dask", "worker", "--scheduler-file", str(address_file), "--nthreads", "1",
                                           "--host", "127.0.0.1", *common],
                                          stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL))
        with Client(scheduler_file=str(address_file), timeout=WAIT) as client:
            client.wait_for_workers(2, timeout=WAIT)
            assert len({pid for pid in client.run(os.getpid).values()} | {os.getpid()}) == 3
            p = run_module(src, tmp_path / "dask.tif", "--scheduler", client.scheduler.address, "--chunk", "128", "-q",
                           *TILE)
            assert p.returncode == 0, p.stderr
            assert same_bits(read(tmp_path / "dask.tif"), want)
            # The run over, its workers hold neither its file open (nor so
            # GDAL's decoded blocks of it) nor its plan.
            assert client.run(held_by_the_steps) == {w: [] for w in client.run(os.getpid)}
            lazy = mcmd.dask.fill(da.from_array(a, chunks=128), nodata=-9999, tile_size=65, tiling="ALWAYS")
            assert same_bits(client.compute(lazy).result(timeout=WAIT), want)
    finally:
        for p in reversed(procs):
            p.terminate()
        for p in procs:
            p.wait(timeout=60)
