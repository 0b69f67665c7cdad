"""Progress, cancellation (a callback, Ctrl-C) and the GIL during a fill."""
import _thread
import filecmp
import os
import signal
import subprocess
import sys
import threading
import time

import numpy as np
import pytest

import mcmd
from conftest import TESTDATA, typed_raster, write

SAMPLE = os.path.join(TESTDATA, "sample_dem.tif")


def big_raster(n=1000):
    """A raster whose fill takes about half a second: one large void."""
    y, x = np.mgrid[0:n, 0:n] / n
    z = (np.sin(7 * x) * np.cos(5 * y) * 100 + 500).astype(np.float32)
    z[n // 4:3 * n // 4, n // 4:3 * n // 4] = np.nan
    return z


def test_progress_reaches_one(tmp_path):
    seen = []
    mcmd.fill_file(SAMPLE, tmp_path / "out.tif", progress=seen.append)
    assert seen and seen[-1] == 1.0 and seen == sorted(seen) and 0.0 <= seen[0] < 1.0
    seen.clear()
    a, nodata = typed_raster("int16")
    mcmd.fill(a, nodata=nodata, progress=seen.append)
    assert seen and seen[-1] == 1.0 and seen == sorted(seen)


def test_progress_is_called_from_the_calling_thread(tmp_path):
    threads = set()
    mcmd.fill_file(SAMPLE, tmp_path / "out.tif", progress=lambda f: threads.add(threading.get_ident()))
    assert threads == {threading.get_ident()}


@pytest.mark.parametrize("dst", ["out.tif", "out.png", None])
def test_cancel_leaves_nothing(tmp_path, dst):
    src = tmp_path / "src.tif"
    a, nodata = typed_raster("uint16")
    write(src, a, nodata)
    before = src.read_bytes()
    with pytest.raises(mcmd.Cancelled, match="cancelled by the user"):
        mcmd.fill_file(src, None if dst is None else tmp_path / dst, progress=lambda f: False)
    assert os.listdir(tmp_path) == ["src.tif"]
    assert src.read_bytes() == before


def test_cancel_later_and_from_fill(tmp_path):
    calls = []

    def stop_at_second_call(f):
        calls.append(f)
        return len(calls) < 2

    with pytest.raises(mcmd.Cancelled):
        mcmd.fill_file(SAMPLE, tmp_path / "out.tif", progress=stop_at_second_call, tiling="ALWAYS", tile_size=65)
    assert len(calls) == 2 and os.listdir(tmp_path) == []
    a, nodata = typed_raster("int16")
    with pytest.raises(mcmd.Cancelled):
        mcmd.fill(a, nodata=nodata, progress=lambda f: 0)
    assert mcmd.fill(a, nodata=nodata, progress=lambda f: None) is not None  # None goes on


def test_callback_exception_propagates(tmp_path):
    def broken(f):
        raise ZeroDivisionError("from the callback")

    with pytest.raises(ZeroDivisionError, match="from the callback"):
        mcmd.fill_file(SAMPLE, tmp_path / "out.tif", progress=broken)
    assert os.listdir(tmp_path) == []
    with pytest.raises(TypeError, match="progress must be callable"):
        mcmd.fill_file(SAMPLE, tmp_path / "out.tif", progress=0.5)


def test_ctrl_c_interrupts_fill():
    z = big_raster()
    timer = threading.Timer(0.05, _thread.interrupt_main)  # SIGINT's effect, from another thread
    start = time.monotonic()
    timer.start()
    with pytest.raises(KeyboardInterrupt):
        mcmd.fill(z, threads=1)
    interrupted = time.monotonic() - start
    timer.join()
    start = time.monotonic()
    mcmd.fill(z, threads=1)
    # Stopped at the fill's next progress report, not raised once it was over.
    assert interrupted < 0.6 * (time.monotonic() - start)


def test_sigint_cancels_fill_file_cleanly(tmp_path):
    src = write(tmp_path / "big.tif", big_raster(1200))
    out_dir = tmp_path / "out"
    out_dir.mkdir()
    script = "import sys, mcmd\nmcmd.fill_file(sys.argv[1], sys.argv[2])\nprint('finished')\n"
    child = subprocess.Popen([sys.executable, "-c", script, src, str(out_dir / "filled.tif")],
                             stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    deadline = time.monotonic() + 30
    while not os.listdir(out_dir) and child.poll() is None and time.monotonic() < deadline:
        time.sleep(0.001)  # until the fill has made its temporary output
    child.send_signal(signal.SIGINT)
    out, err = child.communicate(timeout=60)
    assert child.returncode != 0 and "KeyboardInterrupt" in err and "finished" not in out, err
    assert os.listdir(out_dir) == []


def test_gil_is_released_during_a_fill():
    z = big_raster()
    counts = []
    stop = threading.Event()

    def count():
        while not stop.is_set():
            counts.append(time.monotonic())

    worker = threading.Thread(target=count)
    worker.start()
    time.sleep(0.01)
    start = time.monotonic()
    mcmd.fill(z, threads=1)
    end = time.monotonic()
    stop.set()
    worker.join()
    during = [t for t in counts if start < t < end]
    assert end - start > 0.1
    # The Python thread ran all along, not only at the progress reports.
    assert len(during) > 10000 and max(np.diff([start] + during + [end])) < 0.5 * (end - start)


def test_fills_in_threads_side_by_side():
    a, nodata = typed_raster("float32")
    alone = [mcmd.fill(a, nodata=nodata, rs="auto", seed=seed, threads=1) for seed in range(4)]
    together = [None] * 4

    def run(seed):
        together[seed] = mcmd.fill(a, nodata=nodata, rs="auto", seed=seed, threads=1)

    workers = [threading.Thread(target=run, args=(seed,)) for seed in range(4)]
    for w in workers:
        w.start()
    for w in workers:
        w.join()
    assert all(x.tobytes() == y.tobytes() for x, y in zip(alone, together))
