#!/usr/bin/python3
"""Dask benchmark: python3 -m mcmd.dask against the CLI, on one machine.

Two cases with blob voids (~5 % of the area, seed 0): a 2000x2000 crop of
the Sierra Nevada mosaic and the 10801x4801 mosaic (52 M cells). Each is
filled by ``mcmd_fillnodata`` and by ``python3 -m mcmd.dask`` on

* the threaded scheduler in its own process (the command's default),
* a LocalCluster of 2 worker processes (1 thread each; ``--scheduler``),
* a cluster of ``dask scheduler`` and 2 ``dask worker`` processes
  (1 thread each; ``--scheduler``),

runs interleaved (CLI, threads, LocalCluster, processes, CLI, ...). Wall and
CPU time of each command (on a cluster: the command's own plus the workers',
read from /proc; the clusters are started before and their start-up is not
counted), peak RSS of the command and of the largest worker, and whether the
outputs are bit-identical to the CLI's. Medians. Writes bench/DASK.md.

    /usr/bin/python3 bench/dask_fill.py [--mcmd build/bin/mcmd_fillnodata] [--runs 3]
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
MODES = ["cli", "threads", "local", "processes"]
LABELS = {"cli": "`mcmd_fillnodata`", "threads": "`python3 -m mcmd.dask`, threaded scheduler",
          "local": "`python3 -m mcmd.dask`, LocalCluster of 2 processes",
          "processes": "`python3 -m mcmd.dask`, `dask scheduler` + 2 `dask worker` processes"}


NOTE = ("Where the time goes: on the 2000² crop, starting Python and importing numpy, GDAL and Dask "
        "(0.5–1 s) and, on a cluster, sending the tasks and results between processes weigh as much as "
        "the fill itself; on the mosaic the chunked fill's steps cost about 1.9 times the CLI's CPU on "
        "threads (each chunk's summary and solve read and scan its margin as well, and the four steps "
        "run one after the other with a barrier after the summaries) and 2.6–2.8 times on processes "
        "(solutions serialised, each worker building the plan once).")


def worker_stats():
    """On a worker: (CPU seconds, peak RSS MB) of its process."""
    import resource
    with open("/proc/self/status") as f:
        hwm = next(int(line.split()[1]) for line in f if line.startswith("VmHWM"))
    r = resource.getrusage(resource.RUSAGE_SELF)
    return r.ru_utime + r.ru_stime, hwm / 1024.0


class ProcessCluster:
    """`dask scheduler` and 2 `dask worker` processes on localhost."""

    def __init__(self, folder):
        self.file = os.path.join(folder, "scheduler.json")
        quiet = {"stdout": subprocess.DEVNULL, "stderr": subprocess.DEVNULL}
        self.procs = [subprocess.Popen(["dask", "scheduler", "--host", "127.0.0.1", "--port", "0", "--no-dashboard",
                                        "--scheduler-file", self.file], **quiet)]
        while not os.path.exists(self.file):
            time.sleep(0.1)
        for _ in range(2):
            self.procs.append(subprocess.Popen(["dask", "worker", "--scheduler-file", self.file, "--nthreads", "1",
                                                "--host", "127.0.0.1", "--no-dashboard"], **quiet))

    def close(self):
        for p in reversed(self.procs):
            p.terminate()
        for p in self.procs:
            p.wait(timeout=60)


def run_case(a, name, dem, crop, work):
    from distributed import Client, LocalCluster
    src_dem = V.source_path(dem, crop, work, f"{dem}_crop" if crop else None)
    src = os.path.join(work, f"{os.path.basename(src_dem)[:-4]}__blobs__s0.tif")
    info = V.make_voided(src_dem, src, "blobs", 0)
    outs = {m: os.path.join(work, f"{m}.tif") for m in MODES}
    rows = {m: [] for m in MODES}
    local = LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None)
    procs = ProcessCluster(work)
    clients = {"local": Client(local), "processes": Client(scheduler_file=procs.file)}
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
                r = V.run_timed(cmd)
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
    ref = V.pixel_md5(outs["cli"])
    same = {m: V.pixel_md5(outs[m]) == ref for m in MODES}
    return info, rows, same


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--mcmd", default=os.path.join(V.ROOT_DIR, "build", "bin", "mcmd_fillnodata"))
    ap.add_argument("--runs", type=int, default=3)
    a = ap.parse_args()
    # The workers and the command import this checkout's build, not whichever
    # checkout registered itself last (scripts/install-python.sh).
    package = os.path.join(V.ROOT_DIR, "build", "python")
    os.environ["PYTHONPATH"] = os.pathsep.join(p for p in (package, os.environ.get("PYTHONPATH")) if p)
    sys.path.insert(0, package)
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
    for name, dem, crop in CASES:
        info, rows, same = run_case(a, name, dem, crop, work)
        med = {m: {k: statistics.median(r[k] for r in rows[m]) for k in ("wall", "cpu", "rss", "worker")}
               for m in MODES}
        for m in MODES:
            rss = f"{med[m]['rss']:.0f}" + (f", worker {med[m]['worker']:.0f}" if med[m]["worker"] else "")
            lines.append(f"| {name} | {LABELS[m]} | {med[m]['wall']:.2f} | {med[m]['wall'] / med['cli']['wall']:.2f} "
                         f"| {med[m]['cpu']:.2f} | {med[m]['cpu'] / med['cli']['cpu']:.2f} | {rss} | "
                         f"{'yes' if same[m] else '**no**'} |")
    lines += ["", NOTE, ""]
    with open(os.path.join(V.BENCH_DIR, "DASK.md"), "w") as f:
        f.write("\n".join(lines))
    print("\n".join(lines))


if __name__ == "__main__":
    main()
