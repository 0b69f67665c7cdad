"""End to end through qgis_process, the way a headless user or a CI job runs the provider.

Debian's /usr/bin/qgis_process wrapper is broken (it passes --noversioncheck), so the
real binary /usr/bin/qgis_process.bin is called. The executable is found on PATH (the
provider's last fallback); the plugin through QGIS_PLUGINPATH; the profile lives in a
throw-away HOME.
"""

import os
import re
import shutil
import subprocess
import zipfile

import numpy as np
import pytest

from conftest import REPO, cli_path, plugin_root, run_cli, write_lines
from test_provider import assert_same_raster, read_bands

QGIS_PROCESS = '/usr/bin/qgis_process.bin'


@pytest.fixture()
def qp_env(tmp_path):
    if not os.path.exists(QGIS_PROCESS):
        pytest.fail(f'{QGIS_PROCESS} is missing (package qgis)')
    home = tmp_path / 'home'
    home.mkdir()
    env = dict(os.environ)
    for var in ('XDG_DATA_HOME', 'XDG_CONFIG_HOME', 'QGIS_CUSTOM_CONFIG_PATH'):
        env.pop(var, None)
    env.update({
        'HOME': str(home),
        'QT_QPA_PLATFORM': 'offscreen',
        'XDG_RUNTIME_DIR': str(tmp_path / 'runtime'),
        'QGIS_PLUGINPATH': plugin_root(),
        'PATH': os.path.dirname(cli_path()) + os.pathsep + env.get('PATH', '/usr/bin:/bin'),
        'PYTHONDONTWRITEBYTECODE': '1',
    })
    os.makedirs(env['XDG_RUNTIME_DIR'], mode=0o700)
    return env


def qgis_process(env, *args, check=True):
    proc = subprocess.run([QGIS_PROCESS] + list(args), env=env, stdin=subprocess.DEVNULL,
                          capture_output=True, text=True, timeout=300)
    if check and proc.returncode != 0:
        raise AssertionError(f'qgis_process {" ".join(args)} failed ({proc.returncode}):\n'
                             f'{proc.stdout}\n{proc.stderr}')
    return proc


def test_qgis_process_fills_like_the_cli(qp_env, cli, data, tmp_path):
    enabled = qgis_process(qp_env, 'plugins', 'enable', 'mcmd_provider')
    assert 'mcmd_provider' in enabled.stdout + enabled.stderr

    listing = qgis_process(qp_env, 'list')
    assert 'mcmd:fillnodata' in listing.stdout

    src = data('peaks_int16_geo.tif')
    out = str(tmp_path / 'qp.tif')
    ref = str(tmp_path / 'cli.tif')
    run_cli(cli, ['-q', data('peaks_int16_geo.tif', 'cli'), ref])
    run = qgis_process(qp_env, 'run', 'mcmd:fillnodata', '--', f'INPUT={src}', f'OUTPUT={out}')
    # The command is logged, and the tool found on PATH.
    assert 'mcmd_fillnodata command:' in run.stdout
    # The log's command output holds what the tool printed.
    assert '100 - done.' in run.stdout.split('mcmd_fillnodata command output:')[1]
    assert shutil.which('mcmd_fillnodata', path=qp_env['PATH']) in run.stdout
    assert_same_raster(out, ref)
    _, _, [(before, nodata, _)] = read_bands(src)
    _, _, [(after, _, _)] = read_bands(out)
    assert (before == nodata).any() and not (after == nodata).any()


def test_qgis_process_reports_the_tool_error(qp_env, data, tmp_path):
    qgis_process(qp_env, 'plugins', 'enable', 'mcmd_provider')
    out_dir = tmp_path / 'out'
    out_dir.mkdir()
    run = qgis_process(qp_env, 'run', 'mcmd:fillnodata', '--',
                       f'INPUT={data("peaks_int16_geo.tif")}', 'EXTRA=-method no-such-method',
                       f'OUTPUT={out_dir / "x.tif"}', check=False)
    assert run.returncode != 0
    assert 'mcmd_fillnodata: error:' in run.stdout + run.stderr
    assert os.listdir(out_dir) == []


def test_zip_and_install_scripts(tmp_path):
    """The zip holds mcmd_provider/ at its top (what Install from ZIP wants)."""
    out = tmp_path / 'mcmd_provider.zip'
    subprocess.run(['sh', os.path.join(REPO, 'qgis', 'make_zip.sh'), str(out)], check=True,
                   capture_output=True)
    with zipfile.ZipFile(out) as archive:
        names = archive.namelist()
    assert 'mcmd_provider/metadata.txt' in names and 'mcmd_provider/__init__.py' in names
    assert all(name.startswith('mcmd_provider/') for name in names)
    assert not any('__pycache__' in name for name in names)

    plugins = tmp_path / 'plugins'
    env = dict(os.environ, QGIS_PLUGINS_DIR=str(plugins))
    subprocess.run(['sh', os.path.join(REPO, 'qgis', 'install.sh'), '--cli', cli_path()],
                   check=True, capture_output=True, env=env)
    assert (plugins / 'mcmd_provider' / 'metadata.txt').is_file()
    assert os.access(plugins / 'mcmd_provider' / 'bin' / 'mcmd_fillnodata', os.X_OK)


def test_qgis_process_inner_only_and_void_cap(qp_env, cli, data, tmp_path):
    qgis_process(qp_env, 'plugins', 'enable', 'mcmd_provider')
    help_text = qgis_process(qp_env, 'help', 'mcmd:fillnodata').stdout
    assert 'INNER_ONLY' in help_text and 'MAX_VOID' in help_text and 'FILL_FROM' in help_text
    # The full help, not only its first sentences.
    assert 'Fill only inner holes' in help_text and 'Δ form' in help_text
    cases = [(['INNER_ONLY=true'], ['-inner']), (['MAX_VOID=20'], ['-maxvoid', '20'])]
    for k, (params, flags) in enumerate(cases):
        # Fresh copies: QGIS leaves statistics beside the layers it opened.
        src = data('peaks_int16_geo.tif', f'in{k}')
        out = str(tmp_path / 'qp.tif')
        ref = str(tmp_path / 'cli.tif')
        run_cli(cli, ['-q', *flags, data('peaks_int16_geo.tif', f'cli{k}'), ref])
        qgis_process(qp_env, 'run', 'mcmd:fillnodata', '--', f'INPUT={src}', *params, f'OUTPUT={out}')
        assert_same_raster(out, ref)
        _, _, [(before, nodata, _)] = read_bands(src)
        _, _, [(after, _, _)] = read_bands(out)
        # Some voids are left, others filled.
        assert 0 < (after == nodata).sum() < (before == nodata).sum()
        os.remove(out)
        os.remove(ref)


def test_qgis_process_names_as_gdal_fillnodata_and_unknown_names_refused(qp_env, cli, data, tmp_path):
    qgis_process(qp_env, 'plugins', 'enable', 'mcmd_provider')
    out = str(tmp_path / 'qp.tif')
    ref = str(tmp_path / 'cli.tif')
    run_cli(cli, ['-q', '-md', '2', data('peaks_int16_geo.tif', 'cli'), ref])
    qgis_process(qp_env, 'run', 'mcmd:fillnodata', '--', f'INPUT={data("peaks_int16_geo.tif")}', 'DISTANCE=2',
                 f'OUTPUT={out}')
    assert_same_raster(out, ref)
    # A name QGIS does not know would run with its default: refused instead.
    bad = qgis_process(qp_env, 'run', 'mcmd:fillnodata', '--', f'INPUT={data("peaks_int16_geo.tif", "in2")}',
                       'MAX_DISTANCE=2', f'OUTPUT={tmp_path / "bad.tif"}', check=False)
    assert bad.returncode != 0
    assert 'Unknown parameter MAX_DISTANCE (use DISTANCE' in bad.stdout + bad.stderr
    assert not os.path.exists(tmp_path / 'bad.tif')


def test_qgis_process_fill_from(qp_env, cli, data, tmp_path):
    qgis_process(qp_env, 'plugins', 'enable', 'mcmd_provider')
    second = data('peaks_truth_float32.tif', 'second')
    ref = str(tmp_path / 'cli.tif')
    run_cli(cli, ['-q', '-fill-from', data('peaks_truth_float32.tif', 'second_cli'),
                  data('peaks_float32_utm.tif', 'cli'), ref])
    out = str(tmp_path / 'qp.tif')
    qgis_process(qp_env, 'run', 'mcmd:fillnodata', '--', f'INPUT={data("peaks_float32_utm.tif")}',
                 f'FILL_FROM={second}', f'OUTPUT={out}')
    assert_same_raster(out, ref)
    plain = str(tmp_path / 'plain.tif')
    run_cli(cli, ['-q', data('peaks_float32_utm.tif', 'cli2'), plain])
    _, _, [(a, _, _)] = read_bands(out)
    _, _, [(b, _, _)] = read_bands(plain)
    assert a.tobytes() != b.tobytes()


def test_qgis_process_morphology_and_lines(qp_env, cli, data, tmp_path):
    qgis_process(qp_env, 'plugins', 'enable', 'mcmd_provider')
    help_text = qgis_process(qp_env, 'help', 'mcmd:fillnodata').stdout
    assert 'MORPH' in help_text and 'RIVERS' in help_text and 'RIDGES' in help_text
    assert 'Carry valleys through the voids' in help_text
    _, _, [(z, nodata, _)] = read_bands(data('sample_dem.tif', 'look'))
    # A river across the widest row of void cells, from a known cell to a known cell.
    y = int(np.argmax((z == nodata).sum(axis=1)))
    cols = np.flatnonzero(z[y] == nodata)
    river = [(max(0, cols[0] - 3), y), (min(z.shape[1] - 1, cols[-1] + 3), y)]
    rivers = str(tmp_path / 'rivers.geojson')
    write_lines(rivers, [river], x0=350000.0, y0=4110000.0)
    plain = str(tmp_path / 'plain.tif')
    run_cli(cli, ['-q', data('sample_dem.tif', 'plain'), plain])
    cases = [(['MORPH=true'], ['-morph', 'auto']), ([f'RIVERS={rivers}'], ['-rivers', rivers])]
    for k, (params, flags) in enumerate(cases):
        out, ref = str(tmp_path / f'qp{k}.tif'), str(tmp_path / f'cli{k}.tif')
        run_cli(cli, ['-q', *flags, data('sample_dem.tif', f'cli{k}'), ref])
        qgis_process(qp_env, 'run', 'mcmd:fillnodata', '--', f'INPUT={data("sample_dem.tif", f"in{k}")}',
                     *params, f'OUTPUT={out}')
        assert_same_raster(out, ref)
        _, _, [(a, _, _)] = read_bands(out)
        _, _, [(b, _, _)] = read_bands(plain)
        assert a.tobytes() != b.tobytes(), params  # the option reached the fill


def test_qgis_process_runs_models_of_gdal_fillnodata(qp_env, cli, data, tmp_path):
    """BAND and ITERATIONS, as gdal:fillnodata names them, and RS in elevation units."""
    qgis_process(qp_env, 'plugins', 'enable', 'mcmd_provider')
    out, ref = str(tmp_path / 'qp.tif'), str(tmp_path / 'cli.tif')
    run_cli(cli, ['-q', '-b', '2', '-rs', '20m', data('peaks_2band.tif', 'cli'), ref])
    run = qgis_process(qp_env, 'run', 'mcmd:fillnodata', '--', f'INPUT={data("peaks_2band.tif")}', 'BAND=2',
                       'ITERATIONS=3', 'RS=20m', 'DISTANCE=0', 'NO_MASK=false', 'OPTIONS=', f'OUTPUT={out}')
    assert_same_raster(out, ref)
    assert 'ITERATIONS=3 is ignored' in run.stdout + run.stderr
    assert ' -b 2 ' in run.stdout and ' -rs 20m ' in run.stdout


def test_qgis_process_help_is_plain_text(qp_env):
    qgis_process(qp_env, 'plugins', 'enable', 'mcmd_provider')
    for alg in ('mcmd:fillnodata', 'mcmd:terrain'):
        text = qgis_process(qp_env, 'help', alg).stdout
        description = text.split('Description')[1].split('Arguments')[0]
        assert not re.search(r'</?[a-zA-Z][^>]*>|&[a-z]+;', description), description
        lines = description.splitlines()
        assert all(len(line) < 2000 for line in lines)
    text = qgis_process(qp_env, 'help', 'mcmd:fillnodata').stdout
    assert '\nRS, roughness: 0 (default): a smooth fill.' in text
    assert '\nI, I_BU, DELTA, RT (paper methods only): ' in text
    assert 'I: Paper methods only: top-down interpolation shape I' in text


def assert_bars_apart(stdout):
    """Each progress bar (qgis_process's own, the tool's in the log) on a line of its own."""
    for line in stdout.splitlines():
        if re.search(r'\d\.\.\.', line):
            numbers = [int(n) for n in re.findall(r'\d+', line)]
            assert numbers == sorted(set(numbers)) and numbers[0] == 0, line


def test_qgis_process_error_once_and_progress_lines_apart(qp_env, data, tmp_path):
    qgis_process(qp_env, 'plugins', 'enable', 'mcmd_provider')
    bad = qgis_process(qp_env, 'run', 'mcmd:fillnodata', '--', f'INPUT={data("peaks_int16_geo.tif")}',
                       'EXTRA=-method no-such-method', f'OUTPUT={tmp_path / "x.tif"}', check=False)
    assert bad.returncode != 0
    assert (bad.stdout + bad.stderr).count('METHOD=no-such-method is invalid') == 1, bad.stdout + bad.stderr
    # A failure after the progress bar began: the bar ends before anything else is said.
    bad = qgis_process(qp_env, 'run', 'mcmd:terrain', '--', 'WIDTH=65', 'HEIGHT=65', 'RS=0.5',
                       f'OUTPUT={tmp_path / "t.tif"}', check=False)
    assert bad.returncode != 0
    assert (bad.stdout + bad.stderr).count('give it in elevation units') == 1, bad.stdout + bad.stderr
    assert bad.stdout.rstrip().endswith('0...'), bad.stdout
    assert_bars_apart(bad.stdout)
    good = qgis_process(qp_env, 'run', 'mcmd:fillnodata', '--', f'INPUT={data("peaks_int16_geo.tif", "in2")}',
                        f'OUTPUT={tmp_path / "y.tif"}')
    assert good.stdout.count('100 - done.') == 2, good.stdout  # qgis_process's bar and the tool's
    assert_bars_apart(good.stdout)


def test_readme_qgis_process_commands_as_written(qp_env, cli, testdata, tmp_path):
    """The README's qgis_process block, run as written from a clone's root."""
    with open(os.path.join(REPO, 'README.md'), encoding='utf-8') as f:
        readme = f.read()
    blocks = re.findall(r'```sh\n(.*?)```', readme, re.S)
    block = next(b for b in blocks if 'qgis_process.bin run mcmd:fillnodata' in b)
    clone = tmp_path / 'clone'
    (clone / 'testdata').mkdir(parents=True)
    shutil.copyfile(os.path.join(testdata, 'sample_dem.tif'), clone / 'testdata' / 'sample_dem.tif')
    os.symlink(os.path.join(REPO, 'qgis'), clone / 'qgis')
    os.symlink(os.path.dirname(os.path.dirname(cli)), clone / 'build')
    env = dict(qp_env, PATH=os.environ.get('PATH', '/usr/bin:/bin'))
    env.pop('QGIS_PLUGINPATH')
    run = subprocess.run(['bash', '-e', '-c', block], cwd=clone, env=env, capture_output=True, text=True,
                         timeout=600)
    assert run.returncode == 0, run.stdout + run.stderr
    ref = str(tmp_path / 'cli.tif')
    run_cli(cli, ['-q', '-rs', 'auto', os.path.join(testdata, 'sample_dem.tif'), ref])
    assert_same_raster(str(clone / 'out' / 'sample_qgis.tif'), ref)
    assert 'RS, roughness:' in run.stdout  # the help, last
