"""Shared fixtures for the QGIS provider tests.

Run by ctest (tests/qgis/CMakeLists.txt) as
    QT_QPA_PLATFORM=offscreen MCMD_FILLNODATA=<build>/bin/mcmd_fillnodata \
    QGIS_PLUGINPATH=<repo>/qgis /usr/bin/python3 -m pytest tests/qgis -q
or by hand the same way. Everything here is real: the real CLI, the real QGIS.
The tests skip only when QGIS's Python bindings cannot be imported.
"""

import json
import os
import shutil
import subprocess
import sys

import pytest

REPO = os.path.abspath(os.path.join(os.path.dirname(__file__), '..', '..'))

try:  # QGIS is the one thing allowed to be missing.
    import qgis.core  # noqa: F401
    HAVE_QGIS = True
except ImportError:  # pragma: no cover
    HAVE_QGIS = False


def pytest_collection_modifyitems(config, items):
    if HAVE_QGIS:
        return
    skip = pytest.mark.skip(reason='QGIS Python bindings (python3-qgis) are not importable')
    for item in items:
        item.add_marker(skip)


os.environ.setdefault('QT_QPA_PLATFORM', 'offscreen')


def plugin_root():
    """The folder holding mcmd_provider/: first QGIS_PLUGINPATH entry that has it."""
    for entry in os.environ.get('QGIS_PLUGINPATH', '').split(os.pathsep):
        if entry and os.path.isfile(os.path.join(entry, 'mcmd_provider', 'metadata.txt')):
            return os.path.abspath(entry)
    return os.path.join(REPO, 'qgis')


def cli_path():
    """The real mcmd_fillnodata: $MCMD_FILLNODATA, else build/bin, else PATH."""
    candidates = [os.environ.get('MCMD_FILLNODATA', ''),
                  os.path.join(REPO, 'build', 'bin', 'mcmd_fillnodata'),
                  shutil.which('mcmd_fillnodata') or '']
    for candidate in candidates:
        if candidate and os.path.isfile(candidate) and os.access(candidate, os.X_OK):
            return os.path.abspath(candidate)
    pytest.fail('mcmd_fillnodata not found: set MCMD_FILLNODATA (ctest does) or build it')
    return None


@pytest.fixture(scope='session')
def cli():
    return cli_path()


@pytest.fixture(scope='session')
def testdata():
    return os.path.join(REPO, 'testdata')


@pytest.fixture()
def data(testdata, tmp_path):
    """Copy a testdata file into <tmp>/<where>/ and return the copy's path.

    QGIS writes GDAL .aux.xml side-cars (statistics) next to the layers it opens,
    which GDAL then reads as the file's metadata. Working on copies keeps testdata/
    clean, and giving the direct CLI run its own pristine copy makes the
    comparison independent of what QGIS left behind.
    """
    def copy(name, where='in'):
        folder = tmp_path / where
        folder.mkdir(exist_ok=True)
        src = os.path.join(testdata, name)
        if not os.path.exists(src):
            pytest.fail(f'testdata/{name} is missing')
        dst = str(folder / name)
        shutil.copyfile(src, dst)
        return dst
    return copy


@pytest.fixture(scope='session')
def qgis_app():
    """QGIS application with Processing and the plugin loaded the way QGIS loads it."""
    if '/usr/share/qgis/python/plugins' not in sys.path:
        sys.path.append('/usr/share/qgis/python/plugins')  # the Processing plugin
    from qgis.testing import start_app
    app = start_app()  # offscreen, with a throw-away profile (no user settings touched)

    from processing.core.Processing import Processing
    Processing.initialize()

    import qgis.utils
    root = plugin_root()
    if root not in sys.path:
        sys.path.insert(0, root)
    if root not in qgis.utils.plugin_paths:
        qgis.utils.plugin_paths.insert(0, root)
    qgis.utils.updateAvailablePlugins()
    assert 'mcmd_provider' in qgis.utils.available_plugins
    metadata = qgis.utils.plugins_metadata_parser['mcmd_provider']
    assert metadata.get('general', 'hasProcessingProvider') == 'yes'
    assert qgis.utils.loadPlugin('mcmd_provider')
    assert qgis.utils.startProcessingPlugin('mcmd_provider')
    yield app
    qgis.utils.unloadPlugin('mcmd_provider')


@pytest.fixture()
def use_cli(qgis_app, cli):
    """Point the provider setting at the CLI under test (restored afterwards)."""
    from processing.core.ProcessingConfig import ProcessingConfig
    from mcmd_provider import tool
    old = ProcessingConfig.getSetting(tool.SETTING_EXECUTABLE)
    ProcessingConfig.setSettingValue(tool.SETTING_EXECUTABLE, cli)
    yield cli
    ProcessingConfig.setSettingValue(tool.SETTING_EXECUTABLE, old or '')


def run_cli(cli, args, check=True):
    proc = subprocess.run([cli] + list(args), stdin=subprocess.DEVNULL, capture_output=True,
                          text=True, timeout=600)
    if check and proc.returncode != 0:
        raise AssertionError(f'{cli} {" ".join(args)} failed ({proc.returncode}):\n'
                             f'{proc.stdout}\n{proc.stderr}')
    return proc


def write_lines(path, lines, x0=500000.0, y0=4200000.0, cell=30.0):
    """Pixel polylines as GeoJSON LineStrings in EPSG:32611 (x0, y0: the raster's origin)."""
    features = [{'type': 'Feature', 'properties': {},
                 'geometry': {'type': 'LineString',
                              'coordinates': [[x0 + cell * (x + 0.5), y0 - cell * (y + 0.5)] for x, y in line]}}
                for line in lines]
    with open(path, 'w') as f:
        json.dump({'type': 'FeatureCollection',
                   'crs': {'type': 'name', 'properties': {'name': 'urn:ogc:def:crs:EPSG::32611'}},
                   'features': features}, f)
