"""Running a sweep: serially in this process, or on a Dask cluster.

Both paths share one loop body (`_Collector`): each finished task's rows go to
the table, to the store if there is one (so an interrupted sweep resumes with
what is missing), and to the progress bar (tqdm, on stderr).
"""

import time
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from os import PathLike
from pathlib import Path
from typing import TYPE_CHECKING

from .case import check_fmu, run_task
from .spec import SweepSpec
from .store import CaseStore, to_table

if TYPE_CHECKING:
    import pandas


class _Collector:
    """Rows of finished tasks: stored as they come, counted on a progress bar."""

    def __init__(self, spec, store, progress, label, on_rows):
        from tqdm import tqdm

        self.spec, self.store, self.on_rows = spec, store, on_rows
        self.rows = []
        tasks = spec.tasks()
        self.pending = (
            [cases for cases in (store.missing(t) for t in tasks) if cases]
            if store is not None
            else tasks
        )
        self.bar = tqdm(
            total=sum(len(t) for t in self.pending),
            desc=label,
            unit="case",
            disable=None if progress is None else not progress,  # None: a terminal only
            leave=True,
        )

    def finished(self, rows):
        for row in rows:
            if self.store is not None:
                self.store.write(row)
        self.rows.extend(rows)
        self.bar.update(len(rows))
        if self.on_rows is not None:
            self.on_rows(rows)

    def table(self):
        self.bar.close()
        rows = self.store.rows(self.spec.cases()) if self.store is not None else self.rows
        return to_table(rows, self.spec)


def run_serial(
    fmu: PathLike,
    spec: SweepSpec,
    progress: bool | None = True,
    store: CaseStore | None = None,
    on_rows: Callable[[list], None] | None = None,
) -> "pandas.DataFrame":
    """Every task (every missing one, with a store) in this process, in order;
    returns the table (a DataFrame). `on_rows(rows)` is called after each task;
    `progress`: a bar (None: on a terminal only, never into a log).
    An FMU without the variables the sweep drives is refused before any case."""
    check_fmu(fmu, spec)
    path = str(Path(fmu).resolve())
    collector = _Collector(spec, store, progress, "serial", on_rows)
    try:
        for cases in collector.pending:
            collector.finished(run_task(path, spec, cases))
    finally:
        collector.bar.close()
    return collector.table()


def run_dask(
    fmu: PathLike,
    spec: SweepSpec,
    client,
    progress: bool | None = True,
    store: CaseStore | None = None,
    on_rows: Callable[[list], None] | None = None,
) -> "pandas.DataFrame":
    """Every task (every missing one, with a store) on the client's cluster;
    returns the table (a DataFrame). Rows are stored here as tasks finish; a
    task lost with its worker is rerun by the scheduler and arrives once. An FMU
    without the variables the sweep drives is refused before any case."""
    from dask.distributed import as_completed

    check_fmu(fmu, spec)
    path = str(Path(fmu).resolve())
    collector = _Collector(spec, store, progress, "dask", on_rows)
    tasks = collector.pending
    # pure=False: fresh keys every run, so a repeated sweep is computed again
    # rather than served from the cluster's memory.
    futures = client.map(run_task, [path] * len(tasks), [spec] * len(tasks), tasks, pure=False)
    try:
        for future in as_completed(futures):
            collector.finished(future.result())
    finally:
        collector.bar.close()
        client.cancel(futures)  # an interrupted sweep leaves no work behind
    return collector.table()


def local_cluster(n_workers: int = 2):
    """Worker processes, one thread each: each runs FMUs in its own Python."""
    import dask
    from dask.distributed import LocalCluster

    # On a machine with as many CPUs as workers every background wake-up is
    # taken from the co-simulations. The workers' statistical profiler samples
    # the task thread every 10 ms and fights it for the GIL, which every FMI call
    # releases and retakes (about 20 % of their CPU time); the 20 ms event-loop
    # tick (only a blocked-loop watchdog) cost the scheduler in this process
    # about 1 CPU-s per sweep.
    with dask.config.set(QUIET_CLUSTER):
        return LocalCluster(
            n_workers=n_workers, threads_per_worker=1, processes=True, dashboard_address=None
        )


QUIET_CLUSTER = {
    "distributed.worker.profile.enabled": False,
    "distributed.admin.tick.interval": "1s",
    "distributed.admin.system-monitor.interval": "5s",
}


@contextmanager
def connect(scheduler: str | None = None, n_workers: int = 2) -> Iterator[tuple]:
    """(client, cluster or None, start-up s) for a `with` block: a new LocalCluster
    unless a scheduler address is given. Leaving the block closes the client, and
    the cluster when it is ours (the one teardown of every Dask run)."""
    from dask.distributed import Client

    start = time.perf_counter()
    cluster = None if scheduler else local_cluster(n_workers)
    client = Client(scheduler or cluster)
    try:
        yield client, cluster, time.perf_counter() - start
    finally:
        client.close()
        if cluster is not None:
            cluster.close()


def _import_fmu_stack():
    import fmpy.fmi2  # noqa: F401

    from ..host import simulate  # noqa: F401


def warm_up(client):
    """Import the FMU stack on every worker so that timings compare like with like."""
    client.run(_import_fmu_stack)
