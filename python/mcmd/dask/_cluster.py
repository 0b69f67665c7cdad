"""The LocalCluster that ``python3 -m mcmd.dask --workers N`` starts."""
from __future__ import annotations


def local_cluster(workers: int, threads_per_worker: int = 1):
    """A LocalCluster of `workers` processes on this machine, set up for the
    fill: its messages are not compressed (between processes of one machine
    compression only costs CPU: lz4 took a tenth of the workers' CPU on the
    mosaic) and its workers keep glibc's own malloc tuning (the Nanny's
    MALLOC_TRIM_THRESHOLD_ fixes the mmap threshold at 128 KiB, so every
    window's buffers were mapped and zeroed afresh: a quarter of the workers'
    CPU went to page faults). Nor do its workers sample their own stacks
    for a dashboard it does not start."""
    import dask
    from distributed import LocalCluster
    environ = dict(dask.config.get("distributed.nanny.pre-spawn-environ", default={}))
    environ.pop("MALLOC_TRIM_THRESHOLD_", None)
    with dask.config.set({"distributed.comm.compression": None, "distributed.nanny.pre-spawn-environ": environ,
                          "distributed.worker.profile.enabled": False}):
        return LocalCluster(n_workers=workers, threads_per_worker=threads_per_worker, processes=True,
                            dashboard_address=None)
