#!/usr/bin/python3
"""Dask benchmark: python3 -m mcmd.dask against the CLI, on one machine.

Two cases with blob voids (~5 % of the area, seed 0): a 2000x2000 crop of
the Sierra Nevada mosaic and the 10801x4801 mosaic (52 M cells). Each is
filled by ``mcmd_fillnodata`` and by ``python3 -m mcmd.dask`` on

* the threaded scheduler in its own process (the command's default),
* a LocalCluster of 2 worker processes (1 thread each), set up as
  ``--workers 2`` sets it up (mcmd.dask._cluster), used through ``--scheduler``,
* a cluster of ``dask scheduler`` and 2 ``dask worker`` processes with
  Dask's defaults (1 thread each; ``--scheduler``),
* the same started as docs/dask.md advises: ``dask worker --no-nanny``,
  ``DASK_DISTRIBUTED__COMM__COMPRESSION=None``,

runs interleaved (CLI, threads, LocalCluster, processes, tuned, CLI, ...). Wall and
CPU time of each command (on a cluster: the command's own plus the workers',
read from /proc; the clusters are started before and their start-up is not
counted), peak RSS of the command and of the largest worker, and whether the
outputs are bit-identical to the CLI's. Medians, and the load average seen
before the runs. Every command runs in the environment this script was
started with (a Nanny puts MALLOC_TRIM_THRESHOLD_ into its parent's
environment, which must not reach the CLI or the threaded runs). Writes
bench/DASK.md.

    /usr/bin/python3 bench/dask_fill.py [--mcmd build/bin/mcmd_fillnodata] [--runs 5]
"""
from __future__ import annotations

import argparse
import os
import statistics
import subprocess
import sys
import tempfile
import time

from osgeo import gdal

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import voids as V  # noqa: E402

gdal.UseExceptions()
CASES = [("2000² crop", "ferranti3_sierra_nevada_4801", (1400, 1400, 2000, 2000)),
         ("10801×4801 mosaic", "ferranti3_california_nevada_10801x4801", None)]
MODES = ["cli", "threads", "local", "processes", "tuned"]
LABELS = {"cli": "`mcmd_fillnodata`", "threads": "`python3 -m mcmd.dask`, threaded scheduler",
          "local": "`python3 -m mcmd.dask`, LocalCluster of 2 processes (as `--workers 2`)",
          "processes": "`python3 -m mcmd.dask`, `dask scheduler` + 2 `dask worker` processes",
          "tuned": "`python3 -m mcmd.dask`, the same with `--no-nanny`, no compression"}


NOTE = ("Where the time goes: starting Python and importing numpy, GDAL and Dask takes about 0.3 s of CPU "
        "(0.5–1 s of wall on a busy machine), half of what the CLI takes to fill the whole 2000² crop, and a "
        "cluster's client also imports `distributed` (0.5 s more) and receives every filled chunk: on the crop "
        "no Dask fill comes within 1.5 times the CLI. On the mosaic the chunked fill's own steps cost about what "
        "the CLI's do: a summary reads its rows in strips of whole guide blocks, a process decodes each block of "
        "the file once (the margins come from GDAL's block cache), and the solve and the blend are the CLI's code. "
        "Two of Dask's defaults for worker processes cost CPU: the Nanny's `MALLOC_TRIM_THRESHOLD_` (every "
        "window's buffers mapped and zeroed afresh) and lz4 between processes. The `dask worker` row pays both; "
        "the LocalCluster (as `--workers 2` starts it) and the last row neither (docs/dask.md).")


def worker_stats():
    """On a worker: (CPU seconds, peak RSS MB) of its process."""
    import resource
    with open("/proc/self/status") as f:
        hwm = next(int(line.split()[1]) for line in f if line.startswith("VmHWM"))
    r = resource.getrusage(resource.RUSAGE_SELF)
    return r.ru_utime + r.ru_stime, hwm / 1024.0


class ProcessCluster:
    """`dask scheduler` and 2 `dask worker` processes on localhost: with
    Dask's defaults, or `tuned` as docs/dask.md advises (no Nanny, so no
    MALLOC_TRIM_THRESHOLD_; messages not compressed)."""

    def __init__(self, folder, env, tuned=False):
        self.file = os.path.join(folder, f"scheduler{'-tuned' if tuned else ''}.json")
        if os.path.exists(self.file):
            os.remove(self.file)
        env = dict(env, DASK_DISTRIBUTED__COMM__COMPRESSION="None") if tuned else env
        quiet = {"stdout": subprocess.DEVNULL, "stderr": subprocess.DEVNULL, "env": env}
        self.procs = [subprocess.Popen(["dask", "scheduler", "--host", "127.0.0.1", "--port", "0", "--no-dashboard",
                                        "--scheduler-file", self.file], **quiet)]
        while not os.path.exists(self.file):
            time.sleep(0.1)
        for _ in range(2):
            self.procs.append(subprocess.Popen(["dask", "worker", "--scheduler-file", self.file, "--nthreads", "1",
                                                "--host", "127.0.0.1", "--no-dashboard"]
                                               + (["--no-nanny"] if tuned else []), **quiet))

    def close(self):
        for p in reversed(self.procs):
            p.terminate()
        for p in self.procs:
            p.wait(timeout=60)


def run_case(a, name, dem, crop, work, env):
    from distributed import Client
    from mcmd.dask._cluster import local_cluster
    src_dem = V.source_path(dem, crop, work, f"{dem}_crop" if crop else None)
    src = os.path.join(work, f"{os.path.basename(src_dem)[:-4]}__blobs__s0.tif")
    info = V.make_voided(src_dem, src, "blobs", 0)
    outs = {m: os.path.join(work, f"{m}.tif") for m in MODES}
    rows = {m: [] for m in MODES}
    loads = []
    local = local_cluster(2, 1)
    procs = ProcessCluster(work, env)
    tuned = ProcessCluster(work, env, tuned=True)
    clients = {"local": Client(local), "processes": Client(scheduler_file=procs.file),
               "tuned": Client(scheduler_file=tuned.file)}
    try:
        for c in clients.values():
            c.wait_for_workers(2)
        module = [sys.executable, "-m", "mcmd.dask", src, None, "-q"]
        for run in range(a.runs):
            for m in MODES:
                if m == "cli":
                    cmd = [a.mcmd, "-q", src, outs[m]]
                else:
                    cmd = module[:4] + [outs[m], "-q"]
                    if m in clients:
                        cmd += ["--scheduler", clients[m].scheduler.address]
                before = clients[m].run(worker_stats) if m in clients else {}
                loads.append(os.getloadavg()[0])
                r = V.run_timed(cmd, env=env)
                assert r["rc"] == 0, r["stderr"]
                row = {"wall": r["wall_s"], "cpu": r["user_s"] + r["sys_s"], "rss": r["rss_mb"], "worker": 0.0}
                if m in clients:
                    after = clients[m].run(worker_stats)
                    row["cpu"] += sum(after[w][0] - before.get(w, (0, 0))[0] for w in after)
                    row["worker"] = max(v[1] for v in after.values())
                rows[m].append(row)
                print(f"{name} run {run + 1} {m}: {row['wall']:.2f} s wall, {row['cpu']:.2f} s CPU", flush=True)
    finally:
        for c in clients.values():
            c.close()
        local.close()
        procs.close()
        tuned.close()
    ref = V.pixel_md5(outs["cli"])
    same = {m: V.pixel_md5(outs[m]) == ref for m in MODES}
    return info, rows, same, loads


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--mcmd", default=os.path.join(V.ROOT_DIR, "build", "bin", "mcmd_fillnodata"))
    ap.add_argument("--runs", type=int, default=5)
    a = ap.parse_args()
    # The workers and the command import this checkout's build, not whichever
    # checkout registered itself last (scripts/install-python.sh).
    package = os.path.join(V.ROOT_DIR, "build", "python")
    os.environ["PYTHONPATH"] = os.pathsep.join(p for p in (package, os.environ.get("PYTHONPATH")) if p)
    sys.path.insert(0, package)
    env = dict(os.environ)
    work = os.path.join(V.BENCH_DIR, "work", "dask")
    os.makedirs(work, exist_ok=True)
    lines = [
        "# Region-scale fills on Dask",
        "",
        "Made by `bench/dask_fill.py` (its docstring says how). Machine: 2 cores, 24 GiB RAM, Linux, "
        f"GDAL {gdal.__version__}; the machine was shared with other work while it ran, so wall times "
        "are noisy (CPU time is the steadier measure).",
        "",
        f"Blob voids (5 % of the cells, seed 0). Medians of {a.runs} interleaved runs. `python3 -m mcmd.dask` "
        "with its defaults (chunks of 2048 cells); on the clusters each worker has 1 thread, and the cluster is "
        "started before the command (not counted). CPU = the command's own plus the workers'. RSS: the "
        "command's peak, and the largest worker's.",
        "",
        "| case | fill | wall s | × CLI | CPU s | × CLI | peak RSS MB | bit-identical |",
        "|---|---|---|---|---|---|---|---|",
    ]
    loads = []
    for name, dem, crop in CASES:
        info, rows, same, case_loads = run_case(a, name, dem, crop, work, env)
        loads += case_loads
        med = {m: {k: statistics.median(r[k] for r in rows[m]) for k in ("wall", "cpu", "rss", "worker")}
               for m in MODES}
        for m in MODES:
            rss = f"{med[m]['rss']:.0f}" + (f", worker {med[m]['worker']:.0f}" if med[m]["worker"] else "")
            lines.append(f"| {name} | {LABELS[m]} | {med[m]['wall']:.2f} | {med[m]['wall'] / med['cli']['wall']:.2f} "
                         f"| {med[m]['cpu']:.2f} | {med[m]['cpu'] / med['cli']['cpu']:.2f} | {rss} | "
                         f"{'yes' if same[m] else '**no**'} |")
    lines += ["", f"Load average (1 min) before the runs: median {statistics.median(loads):.1f}, "
              f"{min(loads):.1f}–{max(loads):.1f}, on 2 cores.", "", NOTE, ""]
    with open(os.path.join(V.BENCH_DIR, "DASK.md"), "w") as f:
        f.write("\n".join(lines))
    print("\n".join(lines))


if __name__ == "__main__":
    main()
