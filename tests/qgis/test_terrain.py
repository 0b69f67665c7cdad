"""mcmd:terrain through the real qgis_process, against the real mcmd_terrain.

The algorithm's command must be the tool's: each run is compared cell for cell
with mcmd_terrain run directly with the same options.
"""

import os

import numpy as np
import pytest

from conftest import cli_path, run_cli, write_lines
from test_provider import assert_same_raster, read_bands
from test_qgis_process import qgis_process, qp_env  # noqa: F401 (a fixture)

ALG = 'mcmd:terrain'


@pytest.fixture(scope='module')
def terrain_cli():
    path = os.path.join(os.path.dirname(cli_path()), 'mcmd_terrain')
    if not os.access(path, os.X_OK):
        pytest.fail(f'{path} is missing: build mcmd_terrain')
    return path


def polyline(points):
    """Cells of a polyline through (x, y) points, 8-connected, in order."""
    cells = []
    for (x0, y0), (x1, y1) in zip(points[:-1], points[1:]):
        steps = int(np.ceil(max(abs(x1 - x0), abs(y1 - y0))))
        for s in range(steps + 1):
            c = (int(round(x0 + (x1 - x0) * s / steps)), int(round(y0 + (y1 - y0) * s / steps)))
            if not cells or cells[-1] != c:
                cells.append(c)
    return cells


RIDGES = [[(20, 30), (70, 50), (120, 40)], [(20, 120), (70, 105), (120, 118)]]
RIVER = [(30, 80), (80, 85), (128, 80)]


def write_sketch(folder, n=129):
    """A 16-bit grey sketch (65535 = unknown) of two ridges and a river, and its red/blue states."""
    from osgeo import gdal
    grey = np.full((n, n), 65535, np.uint16)
    rgb = np.zeros((3, n, n), np.uint8)
    for points, (z0, z1), band in [(RIDGES[0], (880, 940), 0), (RIDGES[1], (840, 900), 0),
                                   (RIVER, (480, 80), 2)]:
        cells = polyline(points)
        for k, (x, y) in enumerate(cells):
            grey[y, x] = round(10 * (z0 + (z1 - z0) * k / (len(cells) - 1)))
            rgb[band, y, x] = 255
    mem = gdal.GetDriverByName('MEM').Create('', n, n, 1, gdal.GDT_UInt16)
    mem.GetRasterBand(1).WriteArray(grey)
    gdal.GetDriverByName('PNG').CreateCopy(str(folder / 'sketch.png'), mem)
    mem = gdal.GetDriverByName('MEM').Create('', n, n, 3, gdal.GDT_Byte)
    for b in range(3):
        mem.GetRasterBand(b + 1).WriteArray(rgb[b])
    gdal.GetDriverByName('PNG').CreateCopy(str(folder / 'states.png'), mem)
    return str(folder / 'sketch.png'), str(folder / 'states.png'), grey


def run_terrain(qp_env, *params, check=True):  # noqa: F811
    return qgis_process(qp_env, 'run', ALG, '--', *params, check=check)


def test_terrain_is_listed_with_its_parameters(qp_env):  # noqa: F811
    qgis_process(qp_env, 'plugins', 'enable', 'mcmd_provider')
    assert ALG in qgis_process(qp_env, 'list').stdout
    text = qgis_process(qp_env, 'help', ALG).stdout
    for name in ('SKETCH', 'STATES', 'RIDGES', 'RIVERS', 'GENERATOR', 'WIDTH', 'HEIGHT', 'EXTENT', 'CRS',
                 'METHOD', 'RS', 'H', 'SEED', 'RIDGE_Z', 'RIVER_Z', 'ZRANGE', 'HILLSHADE', 'OUTPUT'):
        assert name in text, name


def test_terrain_from_a_sketch_like_the_cli(qp_env, terrain_cli, tmp_path):  # noqa: F811
    qgis_process(qp_env, 'plugins', 'enable', 'mcmd_provider')
    sketch, states, grey = write_sketch(tmp_path)
    out, ref = str(tmp_path / 'qgis.tif'), str(tmp_path / 'cli.tif')
    run = run_terrain(qp_env, f'SKETCH={sketch}', f'STATES={states}', 'RS=150m', 'H=0.85', 'SEED=3',
                      'ZRANGE=0 6553.5', f'OUTPUT={out}')
    assert 'mcmd_terrain command:' in run.stdout
    run_cli(terrain_cli, ['-q', '-states', states, '-rs', '150m', '-H', '0.85', '-seed', '3',
                          '-zrange', '0', '6553.5', '-of', 'GTiff', sketch, ref])
    assert_same_raster(out, ref)
    _, _, [(z, _, _)] = read_bands(out)
    known = grey != 65535
    assert (z[known] == (grey[known] * (6553.5 / 65535)).astype(np.float32)).all()
    # The river's upper end is lower than the cells beside it, the ridges higher.
    (sx, sy) = polyline(RIVER)[5]
    assert z[sy, sx] < z[sy - 3, sx] and z[sy, sx] < z[sy + 3, sx]
    (rx, ry) = polyline(RIDGES[0])[40]
    assert z[ry, rx] > z[ry - 3, rx] and z[ry, rx] > z[ry + 3, rx]


def test_terrain_from_lines_with_extent_and_crs(qp_env, terrain_cli, tmp_path):  # noqa: F811
    qgis_process(qp_env, 'plugins', 'enable', 'mcmd_provider')
    ridges, rivers = str(tmp_path / 'ridges.geojson'), str(tmp_path / 'rivers.geojson')
    write_lines(ridges, RIDGES)
    write_lines(rivers, [RIVER])
    out, ref, shade = str(tmp_path / 'qgis.tif'), str(tmp_path / 'cli.tif'), str(tmp_path / 'shade.png')
    run_terrain(qp_env, f'RIDGES={ridges}', f'RIVERS={rivers}', 'RIDGE_Z=900', 'RIVER_Z=480,80',
                'WIDTH=129', 'HEIGHT=129', 'EXTENT=500000,503870,4196130,4200000 [EPSG:32611]',
                'CRS=EPSG:32611', 'RS=50m', 'H=0.85', f'HILLSHADE={shade}', f'OUTPUT={out}')
    run_cli(terrain_cli, ['-q', '-size', '129', '129', '-a_ullr', '500000.0', '4200000.0', '503870.0',
                          '4196130.0', '-a_srs', 'EPSG:32611', '-ridges', ridges, '-rivers', rivers, '-rs',
                          '50m', '-H', '0.85', '-ridge-z', '900', '-river-z', '480,80', '-of', 'GTiff', ref])
    assert_same_raster(out, ref)
    gt, wkt, _ = read_bands(out)
    assert gt == (500000.0, 30.0, 0.0, 4200000.0, 0.0, -30.0)
    assert '32611' in wkt
    assert os.path.getsize(shade) > 1000


def test_terrain_skeleton_generator(qp_env, terrain_cli, tmp_path):  # noqa: F811
    qgis_process(qp_env, 'plugins', 'enable', 'mcmd_provider')
    out, ref = str(tmp_path / 'qgis.tif'), str(tmp_path / 'cli.tif')
    run_terrain(qp_env, 'GENERATOR=1', 'WIDTH=200', 'HEIGHT=150', 'METHOD=2', 'RS=0.5', 'I=1', 'I_BU=6',
                'SEED=4', f'OUTPUT={out}')
    run_cli(terrain_cli, ['-q', '-size', '200', '150', '-skeleton', '-method', 'paper-te', '-rs', '0.5',
                          '-seed', '4', '-I', '1.0', '-Ibu', '6.0', '-of', 'GTiff', ref])
    assert_same_raster(out, ref)


def test_terrain_erosion_parameters_like_the_cli(qp_env, terrain_cli, tmp_path):  # noqa: F811
    qgis_process(qp_env, 'plugins', 'enable', 'mcmd_provider')
    text = qgis_process(qp_env, 'help', ALG).stdout
    for name in ('EROSION', 'EROSION_LAW', 'UPLIFT', 'DIFFUSION', 'TALUS'):
        assert name in text, name
    out, ref, off = str(tmp_path / 'qgis.tif'), str(tmp_path / 'cli.tif'), str(tmp_path / 'off.tif')
    run_terrain(qp_env, 'GENERATOR=1', 'WIDTH=129', 'HEIGHT=129', 'RS=0.1', 'SEED=2', 'EROSION=4',
                'EROSION_LAW=auto,0.45,1', 'UPLIFT=uniform', 'DIFFUSION=2', 'TALUS=40', f'OUTPUT={out}')
    run_cli(terrain_cli, ['-q', '-size', '129', '129', '-skeleton', '-rs', '0.1', '-seed', '2', '-diffusion',
                          '2.0', '-talus', '40.0', '-erode', '4', '-erosion', 'auto,0.45,1', '-uplift', 'uniform',
                          '-of', 'GTiff', ref])
    assert_same_raster(out, ref)
    run_terrain(qp_env, 'GENERATOR=1', 'WIDTH=129', 'HEIGHT=129', 'RS=0.1', 'SEED=2', 'EROSION=0',
                f'OUTPUT={off}')
    assert read_bands(off)[2][0][0].tobytes() != read_bands(out)[2][0][0].tobytes()


def test_terrain_error_is_reported_and_nothing_left(qp_env, tmp_path):  # noqa: F811
    qgis_process(qp_env, 'plugins', 'enable', 'mcmd_provider')
    folder = tmp_path / 'out'
    folder.mkdir()
    run = run_terrain(qp_env, 'WIDTH=64', 'HEIGHT=64', 'RS=0.5', f'OUTPUT={folder / "t.tif"}', check=False)
    assert run.returncode != 0
    assert 'elevation units' in run.stdout + run.stderr
    assert os.listdir(folder) == []


def test_terrain_hillshade_beside_its_terrain_and_options(qp_env, tmp_path):  # noqa: F811
    """t.png beside t.tif (the README's first example); OPTIONS as mcmd:fillnodata names it."""
    from osgeo import gdal
    qgis_process(qp_env, 'plugins', 'enable', 'mcmd_provider')
    folder = tmp_path / 'out'
    folder.mkdir()
    run_terrain(qp_env, 'WIDTH=65', 'HEIGHT=65', 'RS=300m', 'SEED=4', 'OPTIONS=COMPRESS=DEFLATE',
                f'HILLSHADE={folder / "t.png"}', f'OUTPUT={folder / "t.tif"}')
    assert sorted(os.listdir(folder)) == ['t.png', 't.tif']
    assert gdal.Open(str(folder / 't.tif')).GetMetadata('IMAGE_STRUCTURE')['COMPRESSION'] == 'DEFLATE'
    assert gdal.Open(str(folder / 't.png')).RasterXSize == 65
    bad = run_terrain(qp_env, 'WIDTH=65', 'HEIGHT=65', 'RS=300m', 'CREATION_OPTIONS=COMPRESS=DEFLATE',
                      f'OUTPUT={folder / "bad.tif"}', check=False)
    assert bad.returncode != 0
    assert 'Unknown parameter CREATION_OPTIONS (use OPTIONS' in bad.stdout + bad.stderr
    assert sorted(os.listdir(folder)) == ['t.png', 't.tif']


def test_terrain_upsample_with_rs_auto_like_the_cli(qp_env, terrain_cli, testdata, tmp_path):  # noqa: F811
    """RS=auto measures a DEM given as the sketch (UPSAMPLE=4), as mcmd_terrain does."""
    from osgeo import gdal
    qgis_process(qp_env, 'plugins', 'enable', 'mcmd_provider')
    coarse = str(tmp_path / 'coarse.tif')
    gdal.Translate(coarse, os.path.join(testdata, 'sample_truth.tif'), srcWin=[0, 0, 129, 129])
    out, ref = str(tmp_path / 'qgis.tif'), str(tmp_path / 'cli.tif')
    run_terrain(qp_env, f'SKETCH={coarse}', 'UPSAMPLE=4', 'RS=auto', f'OUTPUT={out}')
    run_cli(terrain_cli, ['-q', '-upsample', '4', '-rs', 'auto', '-of', 'GTiff', coarse, ref])
    assert_same_raster(out, ref)
    _, _, [(z, _, _)] = read_bands(out)
    assert z.shape == (513, 513)
