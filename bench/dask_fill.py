#!/usr/bin/python3
"""Dask benchmark: python3 -m mcmd.dask on a 2-worker LocalCluster against the CLI.

The 10801x4801 mosaic with blob voids (~5 % of the area, seed 0) is filled by
``mcmd_fillnodata`` and by ``python3 -m mcmd.dask --scheduler <this run's
LocalCluster>`` (2 worker processes, 1 thread each), runs interleaved. Wall
and CPU time of each command (the Dask one: the client's process plus the
workers' CPU, read from /proc), peak RSS of the CLI and of each worker (a new
cluster for each run, so their peak is that run's), and
whether the two outputs are bit-identical. Writes bench/DASK.md.

    /usr/bin/python3 bench/dask_fill.py [--mcmd build/bin/mcmd_fillnodata] [--runs 3] [--chunk 2048]
"""
from __future__ import annotations

import argparse
import os
import statistics
import sys
import time

import numpy as np
from osgeo import gdal

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import voids as V  # noqa: E402

gdal.UseExceptions()
DEM = "ferranti3_california_nevada_10801x4801"


def worker_stats():
    """On a worker: (CPU seconds, peak RSS MB) of its process."""
    import resource
    with open("/proc/self/status") as f:
        hwm = next(int(line.split()[1]) for line in f if line.startswith("VmHWM"))
    r = resource.getrusage(resource.RUSAGE_SELF)
    return r.ru_utime + r.ru_stime, hwm / 1024.0


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--mcmd", default=os.path.join(V.ROOT_DIR, "build", "bin", "mcmd_fillnodata"))
    ap.add_argument("--runs", type=int, default=3)
    ap.add_argument("--chunk", type=int, default=2048)
    a = ap.parse_args()
    # The cluster's workers and the command import this checkout's build,
    # not whichever checkout registered itself last (scripts/install-python.sh).
    package = os.path.join(V.ROOT_DIR, "build", "python")
    os.environ["PYTHONPATH"] = os.pathsep.join(p for p in (package, os.environ.get("PYTHONPATH")) if p)
    sys.path.insert(0, package)
    from distributed import Client, LocalCluster
    work = os.path.join(V.BENCH_DIR, "work", "dask")
    os.makedirs(work, exist_ok=True)
    src = os.path.join(work, f"{DEM}__blobs__s0.tif")
    info = V.make_voided(os.path.join(V.DEM_DIR, DEM + ".tif"), src, "blobs", 0)
    cli_out, dask_out = os.path.join(work, "cli.tif"), os.path.join(work, "dask.tif")
    rows = {"cli": [], "dask": []}
    for run in range(a.runs):
        r = V.run_timed([a.mcmd, "-q", src, cli_out])
        assert r["rc"] == 0, r["stderr"]
        rows["cli"].append({"wall": r["wall_s"], "cpu": r["user_s"] + r["sys_s"], "rss": r["rss_mb"]})
        with LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None) as cluster, \
                Client(cluster) as client:
            client.wait_for_workers(2)
            before = client.run(worker_stats)
            r = V.run_timed([sys.executable, "-m", "mcmd.dask", src, dask_out, "--scheduler",
                             cluster.scheduler_address, "--chunk", str(a.chunk), "-q"])
            assert r["rc"] == 0, r["stderr"]
            after = client.run(worker_stats)
            worker_cpu = sum(after[w][0] - before.get(w, (0, 0))[0] for w in after)
            rows["dask"].append({"wall": r["wall_s"], "cpu": r["user_s"] + r["sys_s"] + worker_cpu,
                                 "rss": r["rss_mb"], "worker_rss": sorted(v[1] for v in after.values())})
            print(f"run {run + 1}: cli {rows['cli'][-1]['wall']:.2f} s, dask {rows['dask'][-1]['wall']:.2f} s",
                  flush=True)
    same = V.pixel_md5(cli_out) == V.pixel_md5(dask_out)
    med = lambda k, key: statistics.median(x[key] for x in rows[k])  # noqa: E731
    worker_peak = statistics.median(max(x["worker_rss"]) for x in rows["dask"])
    lines = [
        "# Region-scale fills on Dask",
        "",
        "Made by `bench/dask_fill.py` (its docstring says how). Machine: 2 cores, 24 GiB RAM, Linux, "
        f"GDAL {gdal.__version__}.",
        "",
        f"The {info['width']}×{info['height']} mosaic ({DEM}) with blob voids "
        f"({100 * info['void_fraction']:.1f} % of the cells), filled by `mcmd_fillnodata` and by "
        f"`python3 -m mcmd.dask` on a LocalCluster of 2 worker processes (1 thread each; chunks of "
        f"{a.chunk} cells, rounded up to a multiple of the tile step). Medians of {a.runs} interleaved runs. "
        "Dask's CPU time is the command's own plus the workers'; its wall time excludes starting the "
        "cluster (an existing scheduler is given).",
        "",
        "| fill | wall s | CPU s | peak RSS MB |",
        "|---|---|---|---|",
        f"| `mcmd_fillnodata` | {med('cli', 'wall'):.2f} | {med('cli', 'cpu'):.2f} | {med('cli', 'rss'):.0f} |",
        f"| `python3 -m mcmd.dask`, 2 workers | {med('dask', 'wall'):.2f} | {med('dask', 'cpu'):.2f} | "
        f"client {med('dask', 'rss'):.0f}, each worker ≤ {worker_peak:.0f} |",
        "",
        f"Outputs bit-identical: **{same}**.",
        "",
    ]
    with open(os.path.join(V.BENCH_DIR, "DASK.md"), "w") as f:
        f.write("\n".join(lines))
    print("\n".join(lines))


if __name__ == "__main__":
    main()
