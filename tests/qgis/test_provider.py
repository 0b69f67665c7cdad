"""mcmd:fillnodata through processing.run(), against the real mcmd_fillnodata."""

import os

import pytest

from conftest import run_cli

ALG = 'mcmd:fillnodata'


def read_bands(path):
    from osgeo import gdal
    ds = gdal.Open(path)
    assert ds is not None, path
    bands = []
    for i in range(1, ds.RasterCount + 1):
        band = ds.GetRasterBand(i)
        bands.append((band.ReadAsArray(), band.GetNoDataValue(), band.DataType))
    return ds.GetGeoTransform(), ds.GetProjection(), bands


def assert_same_raster(a, b):
    """Bit for bit: same file bytes, hence same cells, georeferencing and metadata."""
    with open(a, 'rb') as fa, open(b, 'rb') as fb:
        bytes_a, bytes_b = fa.read(), fb.read()
    if bytes_a == bytes_b:
        return
    # Say what differs before failing.
    gt_a, srs_a, bands_a = read_bands(a)
    gt_b, srs_b, bands_b = read_bands(b)
    assert gt_a == gt_b and srs_a == srs_b
    assert len(bands_a) == len(bands_b)
    for (arr_a, nd_a, dt_a), (arr_b, nd_b, dt_b) in zip(bands_a, bands_b):
        assert (nd_a, dt_a) == (nd_b, dt_b)
        assert arr_a.tobytes() == arr_b.tobytes(), 'cell values differ'
    pytest.fail(f'{a} and {b} have the same cells but differ as files')


class Progress:
    """A feedback that records progress and can cancel itself on the first report."""

    def __init__(self, cancel_at=None):
        from qgis.core import QgsProcessingFeedback
        self.feedback = QgsProcessingFeedback()
        self.values = []
        self.commands = []
        self.cancel_at = cancel_at
        self.feedback.progressChanged.connect(self._on_progress)

    def _on_progress(self, value):
        self.values.append(value)
        if self.cancel_at is not None and value >= self.cancel_at:
            self.feedback.cancel()


def run_alg(params, feedback=None):
    import processing
    from qgis.core import QgsProcessingContext
    context = QgsProcessingContext()
    return processing.run(ALG, params, context=context, feedback=feedback)


# --------------------------------------------------------------------------------------------
# registration


def test_provider_and_algorithm_registered(qgis_app):
    from qgis.core import QgsApplication, QgsProcessingParameterDefinition
    provider = QgsApplication.processingRegistry().providerById('mcmd')
    assert provider is not None
    assert provider.name() == 'MCMD void fill'
    assert not provider.icon().isNull()
    alg = QgsApplication.processingRegistry().algorithmById(ALG)
    assert alg is not None
    assert alg.displayName() == 'Fill nodata (MCMD)'
    assert alg.shortHelpString() and 'RS' in alg.helpString()
    # The help URL is the page shipped in the plugin, the same text as the panel's.
    from qgis.PyQt.QtCore import QUrl
    page = QUrl(alg.helpUrl()).toLocalFile()
    assert page.endswith('mcmd_provider/help/fillnodata.html') and os.path.isfile(page)
    with open(page, encoding='utf-8') as f:
        assert 'INNER_ONLY, fill only inner holes' in f.read()
    # The panel's and qgis_process's text: plain lines, no markup.
    assert '<' not in alg.shortHelpString() and 'INNER_ONLY, fill only inner holes: ' in alg.shortHelpString()
    terrain = QgsApplication.processingRegistry().algorithmById('mcmd:terrain')
    assert os.path.isfile(QUrl(terrain.helpUrl()).toLocalFile())
    names = [p.name() for p in alg.parameterDefinitions()]
    for name in ['INPUT', 'BANDS', 'MASK_LAYER', 'METHOD', 'I', 'I_BU', 'H', 'RT', 'RS', 'SEED',
                 'DISTANCE', 'INNER_ONLY', 'MAX_VOID', 'TILE_SIZE', 'THREADS', 'OPTIONS', 'OUTPUT']:
        assert name in names, name
    advanced = {p.name() for p in alg.parameterDefinitions()
                if p.flags() & QgsProcessingParameterDefinition.FlagAdvanced}
    assert {'I', 'I_BU', 'H', 'RT', 'SEED', 'TILE_SIZE', 'THREADS'} <= advanced
    assert not {'INPUT', 'METHOD', 'RS', 'OUTPUT'} & advanced
    # gdal:fillnodata's names, accepted but not shown.
    hidden = {p.name() for p in alg.parameterDefinitions() if p.flags() & QgsProcessingParameterDefinition.FlagHidden}
    assert hidden == {'BAND', 'ITERATIONS'}
    assert alg.parameterDefinition('METHOD').options()[0].startswith('MCMD')
    assert alg.parameterDefinition('H').defaultValue() == 0.5
    assert alg.parameterDefinition('RS').defaultValue() == '0'


def test_executable_setting_is_a_processing_option(qgis_app):
    from processing.core.ProcessingConfig import ProcessingConfig
    from mcmd_provider import tool
    assert tool.SETTING_EXECUTABLE in ProcessingConfig.settings
    setting = ProcessingConfig.settings[tool.SETTING_EXECUTABLE]
    assert setting.group == 'MCMD void fill'


def test_algorithm_dialog_builds(qgis_app):
    """The toolbox dialog opens (offscreen) with a widget for every parameter."""
    from processing.gui.AlgorithmDialog import AlgorithmDialog
    from qgis.core import QgsApplication
    alg = QgsApplication.processingRegistry().createAlgorithmById(ALG)
    dialog = AlgorithmDialog(alg, False, None)
    dialog.show()
    qgis_app.processEvents()
    wrappers = dialog.mainWidget().wrappers
    shown = {p.name() for p in alg.parameterDefinitions() if not p.flags() & p.FlagHidden}
    assert set(wrappers) == shown
    assert type(wrappers['OPTIONS']).__name__ == 'RasterOptionsWidgetWrapper'
    dialog.close()


# --------------------------------------------------------------------------------------------
# filling


def test_fills_int16_voids_like_the_cli(use_cli, data, tmp_path):
    src = data('peaks_int16_geo.tif')
    out = str(tmp_path / 'qgis.tif')
    ref = str(tmp_path / 'cli.tif')
    run_cli(use_cli, ['-q', data('peaks_int16_geo.tif', 'cli'), ref])
    progress = Progress()
    result = run_alg({'INPUT': src, 'OUTPUT': out}, progress.feedback)
    assert result['OUTPUT'] == out
    assert_same_raster(out, ref)

    # Every void is filled and every known cell kept.
    _, _, [(before, nodata, _)] = read_bands(src)
    _, _, [(after, nodata_after, _)] = read_bands(out)
    assert nodata_after == nodata
    voids = before == nodata
    assert voids.sum() > 0
    assert not (after == nodata).any()
    assert (after[~voids] == before[~voids]).all()

    # GDAL's progress dots reached the feedback, not just the final 100.
    assert max(progress.values) == 100
    assert any(0 < v < 100 for v in progress.values)
    assert progress.values == sorted(progress.values)


@pytest.mark.parametrize('params, cli_args', [
    ({'METHOD': 2, 'I': -0.4, 'I_BU': 6, 'H': 0.4, 'RT': -0.5, 'RS': '0.2', 'SEED': 7},
     ['-method', 'paper-te', '-I', '-0.4', '-Ibu', '6', '-H', '0.4', '-rt', '-0.5', '-rs', '0.2',
      '-seed', '7']),
    ({'RS': 'auto', 'SEED': 3, 'DISTANCE': 5, 'TILE_SIZE': 65, 'THREADS': 2,
      'OPTIONS': 'COMPRESS=DEFLATE|TILED=YES'},
     ['-rs', 'auto', '-seed', '3', '-md', '5', '-tile', '65', '-threads', '2',
      '-co', 'COMPRESS=DEFLATE', '-co', 'TILED=YES']),
])
def test_options_reach_the_cli(use_cli, data, tmp_path, params, cli_args):
    src = data('peaks_float32_utm.tif')
    cli_src = data('peaks_float32_utm.tif', 'cli')
    out = str(tmp_path / 'qgis.tif')
    ref = str(tmp_path / 'cli.tif')
    run_cli(use_cli, ['-q'] + cli_args + [cli_src, ref])
    run_alg(dict(params, INPUT=src, OUTPUT=out))
    assert_same_raster(out, ref)
    # And the options matter: the default run differs.
    plain = str(tmp_path / 'plain.tif')
    run_cli(use_cli, ['-q', cli_src, plain])
    _, _, [(a, _, _)] = read_bands(out)
    _, _, [(b, _, _)] = read_bands(plain)
    assert a.tobytes() != b.tobytes()


def test_band_selection_and_mask(use_cli, data, tmp_path):
    out = str(tmp_path / 'qgis.tif')
    ref = str(tmp_path / 'cli.tif')
    run_cli(use_cli, ['-q', '-b', '2', data('peaks_2band.tif', 'cli'), ref])
    run_alg({'INPUT': data('peaks_2band.tif'), 'BANDS': [2], 'OUTPUT': out})
    assert_same_raster(out, ref)

    out = str(tmp_path / 'qgis_mask.tif')
    ref = str(tmp_path / 'cli_mask.tif')
    run_cli(use_cli, ['-q', '-mask', data('peaks_mask.tif', 'cli'),
                      data('peaks_nonodata.tif', 'cli'), ref])
    run_alg({'INPUT': data('peaks_nonodata.tif'), 'MASK_LAYER': data('peaks_mask.tif'),
             'OUTPUT': out})
    assert_same_raster(out, ref)
    _, _, [(before, _, _)] = read_bands(data('peaks_nonodata.tif', 'cli'))
    _, _, [(after, _, _)] = read_bands(out)
    assert (before != after).any()  # the mask's voids were filled


# --------------------------------------------------------------------------------------------
# cancel and errors


def make_big_dem(path, size=2049):
    """A synthetic Float32 DEM with many voids, big enough to take a while."""
    import numpy as np
    from osgeo import gdal, osr
    y, x = np.mgrid[0:size, 0:size].astype(np.float64) / size
    z = (500 + 300 * np.sin(6 * x) * np.cos(5 * y) + 80 * np.sin(40 * x + 13 * y)).astype(np.float32)
    rng = np.random.default_rng(5)
    for cx, cy, r in zip(rng.integers(0, size, 60), rng.integers(0, size, 60),
                         rng.integers(10, 120, 60)):
        z[max(0, cy - r):cy + r, max(0, cx - r):cx + r] = -9999
    z[rng.random(z.shape) < 0.05] = -9999
    ds = gdal.GetDriverByName('GTiff').Create(path, size, size, 1, gdal.GDT_Float32)
    ds.SetGeoTransform([500000, 10, 0, 4000000, 0, -10])
    srs = osr.SpatialReference()
    srs.ImportFromEPSG(32633)
    ds.SetProjection(srs.ExportToWkt())
    band = ds.GetRasterBand(1)
    band.SetNoDataValue(-9999)
    band.WriteArray(z)
    ds = None


def test_cancel_kills_the_tool_and_leaves_nothing(use_cli, tmp_path):
    from qgis.core import QgsProcessingException
    src = str(tmp_path / 'big.tif')
    make_big_dem(src)
    out_dir = tmp_path / 'out'
    out_dir.mkdir()
    out = str(out_dir / 'filled.tif')
    # Cancel on the first dot the tool prints (2.5 %).
    progress = Progress(cancel_at=2.5)
    with pytest.raises(QgsProcessingException, match='cancel'):
        run_alg({'INPUT': src, 'RS': 'auto', 'OUTPUT': out}, progress.feedback)
    assert progress.feedback.isCanceled()
    assert progress.values and max(progress.values) < 100
    assert not os.path.exists(out)
    assert os.listdir(out_dir) == []


def test_tool_error_line_becomes_the_exception(use_cli, data, tmp_path):
    """An input QGIS opens but the tool refuses: the tool's own error line is reported."""
    from qgis.core import QgsProcessingException
    src = data('all_nodata.tif')
    ref = str(tmp_path / 'cli.tif')
    proc = run_cli(use_cli, ['-q', data('all_nodata.tif', 'cli'), ref], check=False)
    assert proc.returncode != 0
    error = proc.stderr.strip().splitlines()[-1]
    assert error.startswith('mcmd_fillnodata: error:')
    out_dir = tmp_path / 'out'
    out_dir.mkdir()
    out = str(out_dir / 'qgis.tif')
    with pytest.raises(QgsProcessingException) as info:
        run_alg({'INPUT': src, 'OUTPUT': out})
    assert error in str(info.value)
    assert os.listdir(out_dir) == []


def test_bad_option_error_from_the_tool(use_cli, data, tmp_path):
    from qgis.core import QgsProcessingException
    src = data('peaks_int16_geo.tif')
    out = str(tmp_path / 'qgis.tif')
    with pytest.raises(QgsProcessingException, match='mcmd_fillnodata: error:'):
        run_alg({'INPUT': src, 'EXTRA': '-method no-such-method', 'OUTPUT': out})
    assert not os.path.exists(out)


def test_invalid_rs_is_refused_before_running(use_cli, data, tmp_path):
    from qgis.core import QgsProcessingException
    src = data('peaks_int16_geo.tif')
    with pytest.raises(QgsProcessingException, match='RS'):
        run_alg({'INPUT': src, 'RS': 'rough', 'OUTPUT': str(tmp_path / 'x.tif')})
    with pytest.raises(QgsProcessingException, match='2\\^n\\+1'):
        run_alg({'INPUT': src, 'TILE_SIZE': 100, 'OUTPUT': str(tmp_path / 'x.tif')})


def test_missing_executable_is_explained(qgis_app, data, tmp_path):
    from processing.core.ProcessingConfig import ProcessingConfig
    from qgis.core import QgsProcessingException
    from mcmd_provider import tool
    old = ProcessingConfig.getSetting(tool.SETTING_EXECUTABLE)
    not_a_tool = tmp_path / 'mcmd_fillnodata'
    not_a_tool.write_text('not executable')  # exists (the setting accepts it) but cannot run
    ProcessingConfig.setSettingValue(tool.SETTING_EXECUTABLE, str(not_a_tool))
    try:
        with pytest.raises(QgsProcessingException, match='Providers'):
            run_alg({'INPUT': data('peaks_int16_geo.tif'),
                     'OUTPUT': str(tmp_path / 'x.tif')})
    finally:
        ProcessingConfig.setSettingValue(tool.SETTING_EXECUTABLE, old or '')


# --------------------------------------------------------------------------------------------
# pieces


def test_progress_parser_reads_gdal_dots():
    from mcmd_provider.tool import ProgressParser
    seen, text = [], []
    parser = ProgressParser(seen.append, text.append)
    for chunk in ['0', '.', '..10.', '..2', '0...30...40...50...60...70...80...90..', '.100 - done.\n',
                  'Warning 1: something 42\n']:
        parser.feed(chunk)
    parser.close()
    assert seen[0] == 0 and seen[-1] == 100
    assert seen == sorted(seen) and 7.5 in seen and 52.5 in seen
    assert text == ['Warning 1: something 42']
    echoed = []
    parser = ProgressParser(lambda p: None, echoed.append, echo_progress=True)
    parser.feed('0...10...20...30...40...50...60...70...80...90...100 - done.\n')
    parser.close()
    assert echoed == ['0...10...20...30...40...50...60...70...80...90...100 - done.']


def test_remove_outputs_takes_only_what_the_run_left(tmp_path):
    """After a cancel: the output, the tool's temporary name and side-cars go; the rest stays."""
    from mcmd_provider.tool import remove_outputs, snapshot
    (tmp_path / 'filled.tif.aux.xml').write_text('old side-car')  # there before the run
    (tmp_path / 'other.tif').write_text('unrelated')
    before = snapshot(str(tmp_path))
    for name in ['filled.mcmd-tmp-4242.tif', 'filled.mcmd-tmp-4242.tif.aux.xml', 'filled.tif',
                 'unrelated-new.tif', 'prefilled.tif']:
        (tmp_path / name).write_text('x')
    remove_outputs(str(tmp_path / 'filled.tif'), before)
    assert sorted(os.listdir(tmp_path)) == ['filled.tif.aux.xml', 'other.tif',
                                            'prefilled.tif', 'unrelated-new.tif']


def test_result_layer_is_named_after_its_input(use_cli, data, tmp_path):
    import processing
    from qgis.core import QgsProcessingContext, QgsProcessingFeedback, QgsProcessingUtils
    context = QgsProcessingContext()
    out = str(tmp_path / 'named.tif')
    src = data('peaks_int16_geo.tif')
    context.addLayerToLoadOnCompletion(out, QgsProcessingContext.LayerDetails('Filled', context.project(), 'OUTPUT'))
    processing.run(ALG, {'INPUT': src, 'OUTPUT': out}, context=context, feedback=QgsProcessingFeedback())
    assert context.layerToLoadOnCompletionDetails(out).name == 'peaks_int16_geo filled'
