"""Serial against Dask: identical tables, wall times, and how busy the machine was."""

import os
import time
from pathlib import Path

from .case import run_task
from .execution import connect, run_dask, run_serial, warm_up


def timed(function, *args, **kwargs):
    start = time.perf_counter()
    value = function(*args, **kwargs)
    return value, time.perf_counter() - start


def _machine_busy_seconds():
    """CPU-seconds the whole machine has been busy so far (Linux), or None."""
    try:
        with open("/proc/stat") as stream:
            fields = [int(x) for x in stream.readline().split()[1:9]]
    except (OSError, ValueError):
        return None
    user, nice, system, _idle, _iowait, irq, softirq, steal = fields
    return (user + nice + system + irq + softirq + steal) / os.sysconf("SC_CLK_TCK")


def _measured(function, *args, client=None):
    """(value, wall s, CPUs that other processes kept busy meanwhile or None).

    Other jobs on the machine skew wall times; the machine's busy time minus
    this process's (and the local workers') tells how much."""

    def own():
        workers = sum(client.run(time.process_time).values()) if client else 0.0
        return time.process_time() + workers

    busy, mine = _machine_busy_seconds(), own()
    value, seconds = timed(function, *args)
    if busy is None:
        return value, seconds, None
    others = (_machine_busy_seconds() - busy) - (own() - mine)
    return value, seconds, max(others, 0.0) / seconds


def _dask_run(fmu, spec, scheduler, n_workers, progress):
    """(table, sweep s, start-up s, others' CPUs): a fresh cluster per run,
    closed before the serial run so its scheduler cannot slow that run down."""
    with connect(scheduler, n_workers) as (client, cluster, startup):
        warm_up(client)
        table, seconds, others = _measured(
            run_dask, fmu, spec, client, progress, client=client if cluster is not None else None
        )
    return table, seconds, startup, others if cluster is not None else None


def compare(fmu, spec, scheduler=None, n_workers=2, repeat=1, progress=True):
    """Run serially and on Dask `repeat` times; return (table, timings), each
    timing a dict of wall times, cluster start-up and the CPUs that other
    processes kept busy. Raises AssertionError if the tables differ.

    The serial run goes first, with no cluster in this process: a LocalCluster's
    scheduler lives in this process, and its event loop, kept busy by the
    workers, took about a quarter more CPU from a serial run beside it."""
    import pandas as pd

    run_task(str(Path(fmu).resolve()), spec, spec.tasks()[0][:1])  # imports, as workers do
    timings = []
    for _ in range(repeat):
        serial, serial_seconds, serial_others = _measured(run_serial, fmu, spec, progress)
        on_dask, dask_seconds, startup, dask_others = _dask_run(
            fmu, spec, scheduler, n_workers, progress
        )
        pd.testing.assert_frame_equal(on_dask, serial, check_exact=True)
        timings.append(
            {
                "dask": dask_seconds,
                "serial": serial_seconds,
                "startup": startup,
                "others_dask": dask_others,
                "others_serial": serial_others,
            }
        )
    return on_dask, timings
