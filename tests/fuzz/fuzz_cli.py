#!/usr/bin/python3
"""Seeded fuzz run of mcmd_fillnodata (the sanitizer build): mutated small
GeoTIFFs with voids, and random option values, each through the real CLI.

A case fails on a crash (a signal), a sanitizer report (ASan, LSan, UBSan),
a hang (10 s), an exit other than 0 or 1, an error that is not exactly one
"mcmd_fillnodata: error: ..." line, a file left behind, a source changed
(unless filled in place), or an exit 0 whose output changed a valid cell,
left a void that was not asked to stay, or filled one with the nodata value
or NaN. The same seed gives the same cases.

Usage: fuzz_cli.py CLI [--seed N] [--files N] [--options N] [--jobs N]
Needs /usr/bin/python3 with numpy and GDAL's bindings.
"""

import argparse
import concurrent.futures
import os
import random
import shutil
import subprocess
import sys
import tempfile

import numpy as np
from osgeo import gdal

gdal.UseExceptions()
gdal.PushErrorHandler('CPLQuietErrorHandler')

TIMEOUT_S = 10
KEEP = None  # --keep: a folder where failing cases' sources are copied
SANITIZER_MARKS = ('ERROR: AddressSanitizer', 'ERROR: LeakSanitizer', 'runtime error:',
                   'ERROR: ThreadSanitizer', 'WARNING: ThreadSanitizer', 'SUMMARY: ')

TYPES = [(gdal.GDT_Byte, 0), (gdal.GDT_Int16, -32768), (gdal.GDT_UInt16, 65535), (gdal.GDT_Int32, -99999),
         (gdal.GDT_UInt32, 0), (gdal.GDT_Int64, -9999), (gdal.GDT_UInt64, 0), (gdal.GDT_Float32, -9999.0),
         (gdal.GDT_Float64, float('nan')), (gdal.GDT_Float64, -1.7976931348623157e308)]


def sanitizer_env():
    env = dict(os.environ)
    env.setdefault('ASAN_OPTIONS', 'detect_leaks=1:exitcode=86')
    env.setdefault('UBSAN_OPTIONS', 'halt_on_error=1:print_stacktrace=1:exitcode=86')
    env.setdefault('TSAN_OPTIONS', 'halt_on_error=1:exitcode=86')
    return env


# ---------------------------------------------------------------- inputs

def terrain(rng, w, h, gdt):
    y, x = np.mgrid[0:h, 0:w]
    z = 0.5 + 0.25 * np.sin(x * rng.uniform(0.05, 0.4)) * np.cos(y * rng.uniform(0.05, 0.4)) + 0.2 * (x + y) / (w + h)
    if gdt == gdal.GDT_Byte:
        return np.round(20 + 200 * z)
    if gdt in (gdal.GDT_Float32, gdal.GDT_Float64):
        big = rng.random() < 0.2
        return (1e307 if big else 1000.0) * z + (1e307 if big else 0.0)
    return np.round(100 + 3000 * z)


def void_mask(rng, w, h):
    m = np.zeros((h, w), bool)
    for _ in range(rng.integers(1, 5)):
        cx, cy, r = rng.uniform(0, w), rng.uniform(0, h), rng.uniform(0.5, max(w, h) / 3)
        y, x = np.mgrid[0:h, 0:w]
        m |= (x - cx) ** 2 + (y - cy) ** 2 <= r * r
    m |= rng.random((h, w)) < rng.uniform(0, 0.2)
    if m.all():
        m[0, 0] = False
    return m


def make_source(path, rng):
    """A small GeoTIFF with voids: random type, size, layout, compression."""
    gdt, nodata = TYPES[rng.integers(len(TYPES))]
    w, h = int(rng.integers(1, 90)), int(rng.integers(1, 70))
    bands = int(rng.choice([1, 1, 1, 2, 3]))
    co = []
    if rng.random() < 0.5:
        co += ['TILED=YES', 'BLOCKXSIZE=16', 'BLOCKYSIZE=16']
    co.append('COMPRESS=' + str(rng.choice(['NONE', 'LZW', 'DEFLATE', 'ZSTD', 'PACKBITS'])))
    if bands > 1 and rng.random() < 0.5:
        co.append('INTERLEAVE=BAND')
    ds = gdal.GetDriverByName('GTiff').Create(path, w, h, bands, gdt, co)
    ds.SetGeoTransform([350000, 30, 0, 4110000, 0, -30])
    for b in range(1, bands + 1):
        band = ds.GetRasterBand(b)
        z = terrain(rng, w, h, gdt)
        m = void_mask(rng, w, h)
        if gdt == gdal.GDT_Int64:
            band.SetNoDataValueAsInt64(int(nodata))
        elif gdt == gdal.GDT_UInt64:
            band.SetNoDataValueAsUInt64(int(nodata))
        elif rng.random() < 0.9:
            band.SetNoDataValue(nodata)
        z[m] = nodata
        band.WriteArray(z)
    ds = None


def mutate(data, rng):
    """Flip, overwrite, insert or cut bytes of a TIFF file."""
    b = bytearray(data)
    for _ in range(int(rng.integers(1, 8))):
        op = rng.integers(5)
        at = int(rng.integers(len(b))) if b else 0
        if op == 0 and b:
            b[at] ^= 1 << int(rng.integers(8))
        elif op == 1 and b:
            b[at] = int(rng.integers(256))
        elif op == 2:
            b[at:at] = bytes(rng.integers(0, 256, int(rng.integers(1, 16)), dtype=np.uint8))
        elif op == 3:
            del b[at:at + int(rng.integers(1, 64))]
        elif op == 4 and len(b) > 16:
            at = int(rng.integers(4, min(len(b), 400)))  # the header and first directory
            b[at] = int(rng.choice([0, 255, 0x7f, 0x80]))
    if rng.random() < 0.1:
        b = b[:int(rng.integers(len(b) + 1))]
    return bytes(b)


# ---------------------------------------------------------------- options

FORMATS = ['GTiff', 'COG', 'PNG', 'JPEG', 'VRT', 'MEM', 'AAIGrid', 'HFA', 'ENVI', 'netCDF', 'XYZ', 'NoSuch', 'GPKG',
           'MRF', 'JP2OpenJPEG']
EXTENSIONS = {'GTiff': 'tif', 'COG': 'tif', 'PNG': 'png', 'JPEG': 'jpg', 'VRT': 'vrt', 'AAIGrid': 'asc',
              'HFA': 'img', 'ENVI': 'envi', 'netCDF': 'nc', 'XYZ': 'xyz', 'GPKG': 'gpkg', 'MRF': 'mrf',
              'JP2OpenJPEG': 'jp2'}
ABSURD = ['-1', '1e308', '1e-320', '0x10', 'inf', '-inf', 'nan', '', ' 1', '1 ', '1e', '.', '+3',
          '99999999999999999999', 'abc', '1e999']
# Per flag: values in range (most runs), then absurd ones.
FLAGS = {
    '-md': ['0', '1', '2.5', '5.', '40', '1e3', '0.0001'],
    '-I': ['0', '1', '-1', '0.5', '-.5', '100', '-100', '1e2'], '-Ibu': ['0', '2', '-3', '99.9'],
    '-H': ['0', '0.3', '0.5', '0.9', '1', '1e-9'], '-rt': ['0', '-1', '1', '0.25', '-0.75'],
    '-rs': ['0', 'auto', 'AUTO', '0.05', '0.01', '1', '10', '2e-5'],
    '-seed': ['0', '1', '7', '18446744073709551615', '18446744073709551616', 'x'],
    '-tile': ['0', '3', '5', '17', '33', '65', '129', '100', '32769', '65537'],
    '-threads': ['1', '2', '3', 'ALL_CPUS', '1024', '0', '1025'],
    '-method': ['mcmd', 'paper-ds', 'paper-te', 'PAPER_DS', 'kriging'],
    '-delta': ['normalized', 'paper', 'other'],
    '-b': ['1', '2', '3', '0', '9', '+1', 'x'],
    '-maxvoid': ['0', '1', '5', '40', '5cells', '1e3', '2.5', '900m2', '1km2', '1ha', '3acres'],
}


def random_options(rng):
    """Random values of every option: mostly in range, some absurd."""
    opts = []
    for flag in rng.choice(sorted(FLAGS), size=int(rng.integers(1, 5)), replace=False):
        values = FLAGS[flag] if rng.random() < 0.85 or flag in ('-seed', '-tile', '-threads', '-method', '-b') \
            else ABSURD
        opts += [str(flag), str(rng.choice(values))]
    if rng.random() < 0.3:
        opts += ['-o', str(rng.choice(['TILING=ALWAYS', 'TILING=AUTO', 'TILING=NO', 'RIDGE_I=2', 'RIVER_I=-3',
                                       'FOO=1', 'NUM_THREADS=2', 'MAX_DISTANCE=0x5', 'I=1e999']))]
    if rng.random() < 0.25:
        opts += ['-of', str(rng.choice(FORMATS))]
    if rng.random() < 0.2:
        opts += ['-co', str(rng.choice(['COMPRESS=DEFLATE', 'COMPRESS=JPEG', 'TILED=YES', 'NBITS=4',
                                        'COMPRESS=LERC', 'MAX_Z_ERROR=0.5', 'BAD', 'PREDICTOR=2']))]
    if rng.random() < 0.1:
        opts.append('-nomask')
    if rng.random() < 0.15:
        opts.append('-inner')
    return opts


# ---------------------------------------------------------------- checks

def read_bands(path):
    ds = gdal.Open(path)
    out = []
    for b in range(1, ds.RasterCount + 1):
        band = ds.GetRasterBand(b)
        out.append((band.ReadAsArray(), band.GetMaskBand().ReadAsArray(), band.DataType))
    return out


def nodata_of(band):
    if band.DataType == gdal.GDT_Int64:
        return band.GetNoDataValueAsInt64()
    if band.DataType == gdal.GDT_UInt64:
        return band.GetNoDataValueAsUInt64()
    return band.GetNoDataValue()


def output_files(path):
    """The names of the files GDAL says the dataset at path is made of."""
    try:
        return {os.path.basename(f) for f in gdal.Open(path).GetFileList() or []}
    except RuntimeError:
        return set()


def is_nan(v):
    return isinstance(v, float) and np.isnan(v)


def check_output(src_copy, dst, args):
    """Exit 0: every valid cell kept; unless -md, -b, -nomask, -inner or -maxvoid chose otherwise,
    every void filled, with neither the nodata value nor NaN."""
    try:
        src, out = gdal.Open(src_copy), gdal.Open(dst)
    except RuntimeError as e:
        return 'exit 0 but the output cannot be read: %s' % e
    if (src.RasterXSize, src.RasterYSize, src.RasterCount) != (out.RasterXSize, out.RasterYSize, out.RasterCount):
        return 'exit 0 but the output has another size or band count'
    all_filled = not {'-md', '-b', '-nomask', '-inner', '-maxvoid'} & set(args)
    for b in range(1, src.RasterCount + 1):
        sb, ob = src.GetRasterBand(b), out.GetRasterBand(b)
        try:
            z, valid = sb.ReadAsArray(), sb.GetMaskBand().ReadAsArray() != 0
            second = gdal.Open(src_copy)  # held: a band does not keep its dataset alive
            again = second.GetRasterBand(b).ReadAsArray()
        except RuntimeError:
            continue  # a mutated source GDAL cannot read whole here: nothing to compare with
        if again.tobytes() != z.tobytes():
            continue  # GDAL reads this mutated source differently each time (a short DEFLATE strip: memory)
        o = ob.ReadAsArray()
        if z.dtype.kind == 'f':
            valid &= np.isfinite(z)
        same = np.array_equal(o[valid].view(np.uint8), z[valid].view(np.uint8)) if o.dtype == z.dtype \
            else np.array_equal(o[valid], z[valid])
        if not same:
            return 'band %d: valid cells changed' % b
        if not all_filled:
            continue
        filled, nd = o[~valid], nodata_of(sb)
        if filled.dtype.kind == 'f' and not np.isfinite(filled).all():
            return 'band %d: a void left or filled with NaN or infinity' % b
        if nd is not None and not is_nan(nd) and (filled == nd).any():
            return 'band %d: a void left or filled with the nodata value' % b
    return None


def run_case(cli, name, source_bytes, args, in_place, workdir):
    """Run one case in its own folder; returns (exit code, failure or None)."""
    gdal.PushErrorHandler('CPLQuietErrorHandler')  # GDAL's handlers are per thread
    rc, problem = run_and_check(cli, name, source_bytes, args, in_place, workdir)
    if problem and KEEP:
        os.makedirs(KEEP, exist_ok=True)
        shutil.copyfile(os.path.join(workdir, name + '.ref.tif'), os.path.join(KEEP, name + '.tif'))
    shutil.rmtree(os.path.join(workdir, name), ignore_errors=True)
    os.remove(os.path.join(workdir, name + '.ref.tif'))
    return rc, problem


def run_and_check(cli, name, source_bytes, args, in_place, workdir):
    folder = os.path.join(workdir, name)
    os.makedirs(folder)
    src = os.path.join(folder, 'src.tif')
    with open(src, 'wb') as f:
        f.write(source_bytes)
    reference = os.path.join(workdir, name + '.ref.tif')
    shutil.copyfile(src, reference)
    driver = args[args.index('-of') + 1] if '-of' in args else 'GTiff'
    dst = os.path.join(folder, 'out.' + EXTENSIONS.get(driver, 'x'))
    argv = [cli, '-q'] + args + [src] + ([] if in_place else [dst])
    before = sorted(os.listdir(folder))
    try:
        p = subprocess.run(argv, capture_output=True, text=True, errors='replace', timeout=TIMEOUT_S,
                           env=sanitizer_env())
    except subprocess.TimeoutExpired:
        return None, 'hang (over %d s): %s' % (TIMEOUT_S, ' '.join(argv[1:]))
    what = ' '.join(argv[1:])
    if p.returncode < 0:
        return p.returncode, 'crash (signal %d): %s\n%s' % (-p.returncode, what, p.stderr[-2000:])
    if any(m in p.stderr for m in SANITIZER_MARKS):
        return p.returncode, 'sanitizer report: %s\n%s' % (what, p.stderr[-4000:])
    if p.returncode not in (0, 1):
        return p.returncode, 'exit %d: %s\n%s' % (p.returncode, what, p.stderr[-2000:])
    after = sorted(os.listdir(folder))
    if p.returncode == 1:
        lines = p.stderr.splitlines()
        if len(lines) != 1 or not lines[0].startswith('mcmd_fillnodata: error: '):
            return 1, 'error not one line: %s\n%s' % (what, p.stderr[-2000:])
        if after != before:
            return 1, 'left behind %s: %s' % (sorted(set(after) - set(before)), what)
        with open(src, 'rb') as f:
            if f.read() != source_bytes and not (in_place and 'partly filled' in p.stderr):
                return 1, 'source changed by a failed run: %s' % what
        if os.environ.get('MCMD_FUZZ_VERBOSE'):
            print('exit 1:', lines[0][:110])
        return 1, None
    if p.stderr:
        return 0, 'exit 0 with stderr: %s\n%s' % (what, p.stderr[-2000:])
    extra = set(after) - set(before) - {os.path.basename(dst)} - output_files(src if in_place else dst)
    extra = {e for e in extra if not e.startswith('out.') or 'mcmd-tmp' in e}
    if extra:
        return 0, 'left behind %s: %s' % (sorted(extra), what)
    if not in_place:
        with open(src, 'rb') as f:
            if f.read() != source_bytes:
                return 0, 'source changed: %s' % what
    problem = check_output(reference, src if in_place else dst, args)
    return 0, None if problem is None else '%s: %s' % (problem, what)


def cases(seed, n_files, n_options, workdir):
    rng = np.random.default_rng(seed)
    sources = []
    for k in range(12):
        path = os.path.join(workdir, 'base%d.tif' % k)
        make_source(path, rng)
        with open(path, 'rb') as f:
            sources.append(f.read())
    out = []
    for k in range(n_files):
        data = mutate(sources[k % len(sources)], rng)
        args = random_options(rng) if rng.random() < 0.3 else []
        out.append(('file%03d' % k, data, args, rng.random() < 0.15))
    for k in range(n_options):
        out.append(('opts%03d' % k, sources[k % len(sources)], random_options(rng), rng.random() < 0.1))
    return out


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument('cli')
    ap.add_argument('--seed', type=int, default=20240601)
    ap.add_argument('--files', type=int, default=250)
    ap.add_argument('--options', type=int, default=250)
    ap.add_argument('--jobs', type=int, default=2)
    ap.add_argument('--keep', help='copy the sources of failing cases here')
    a = ap.parse_args()
    global KEEP
    KEEP = a.keep
    workdir = tempfile.mkdtemp(prefix='mcmd-fuzz-')
    try:
        todo = cases(a.seed, a.files, a.options, workdir)
        failures = []
        exits = {}
        with concurrent.futures.ThreadPoolExecutor(a.jobs) as pool:
            futures = {pool.submit(run_case, a.cli, n, d, args, ip, workdir): n for n, d, args, ip in todo}
            for fut in concurrent.futures.as_completed(futures):
                rc, problem = fut.result()
                exits[rc] = exits.get(rc, 0) + 1
                if problem:
                    failures.append('%s: %s' % (futures[fut], problem))
        print('fuzz: %d cases (seed %d), exits %s: %d failures'
              % (len(todo), a.seed, dict(sorted(exits.items(), key=str)), len(failures)))
        for f in sorted(failures):
            print('FAIL', f)
        return 1 if failures else 0
    finally:
        shutil.rmtree(workdir, ignore_errors=True)


if __name__ == '__main__':
    sys.exit(main())
