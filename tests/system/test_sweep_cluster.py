"""The design sweep on a cluster started the way a user starts one: a `dask
scheduler` and two `dask worker` processes (loopback addresses only), then an
interrupted sweep resumed, and a worker killed in the middle of a sweep."""

import dataclasses
import json
import os
import signal
import subprocess
import sys
import time

import pytest

from cardan_joint import sweep

pytest.importorskip("dask.distributed")

# 6 tasks of 2 cases: enough that both workers are busy when the first task returns.
TINY = sweep.SweepSpec(
    bend_angles_deg=(5.0, 20.0, 85.0),
    input_speeds_rpm=(1000.0, 3000.0),
    distributions=("T1", "T3"),
    revolutions=1,
    steps_per_revolution=72,
)
QUIET = {
    "DASK_DISTRIBUTED__WORKER__PROFILE__ENABLED": "False",
    "DASK_DISTRIBUTED__ADMIN__TICK__INTERVAL": "1s",
}


class Processes:
    """Processes started by this test, each in its own process group, always killed."""

    def __init__(self, logs):
        self.logs, self.started = logs, []

    def start(self, *args):
        log = open(self.logs / f"{len(self.started)}_{args[0]}.log", "w")
        process = subprocess.Popen(
            [sys.executable, "-m", "dask", *args],
            stdout=log,
            stderr=subprocess.STDOUT,
            start_new_session=True,
            env={**os.environ, **QUIET},
        )
        log.close()
        self.started.append(process)
        return process

    def kill(self, process):
        try:
            os.killpg(process.pid, signal.SIGKILL)  # the worker and its nanny
        except ProcessLookupError:
            pass
        process.wait(timeout=30)

    def kill_all(self):
        for process in self.started:
            self.kill(process)


@pytest.fixture(scope="module")
def cluster(tmp_path_factory):
    """(client, the two `dask worker` processes)."""
    from dask.distributed import Client

    folder = tmp_path_factory.mktemp("cluster")
    address_file = folder / "scheduler.json"
    processes = Processes(folder)
    client = None
    try:
        processes.start(
            "scheduler",
            "--host",
            "127.0.0.1",
            "--port",
            "0",
            "--no-dashboard",
            "--scheduler-file",
            address_file,
        )
        workers = [
            processes.start(
                "worker",
                "--scheduler-file",
                address_file,
                "--host",
                "127.0.0.1",
                "--nthreads",
                "1",
                "--no-dashboard",
            )
            for _ in range(2)
        ]
        deadline = time.monotonic() + 60
        while not address_file.is_file() and time.monotonic() < deadline:
            time.sleep(0.1)
        address = json.loads(address_file.read_text())["address"]
        assert address.startswith("tcp://127.0.0.1:")
        client = Client(address, timeout=60)
        client.wait_for_workers(2, timeout=60)
        yield client, workers
    finally:
        if client is not None:
            client.close()
        processes.kill_all()


@pytest.fixture(scope="module")
def serial(fmu_path):
    return sweep.run_serial(fmu_path, TINY, progress=False)


def case_files(folder):
    return sorted(p.name for p in folder.iterdir() if p.name != sweep.store.SETTINGS_FILE)


def test_an_interrupted_sweep_resumes_with_only_the_missing_cases(
    cluster, fmu_path, serial, tmp_path
):
    import pandas as pd

    client, _ = cluster
    total = len(TINY.cases())

    returned = []

    def interrupt_after_two_tasks(rows):
        returned.append(rows)
        if len(returned) == 2:
            raise KeyboardInterrupt

    first = sweep.CaseStore(tmp_path, TINY)
    with pytest.raises(KeyboardInterrupt):
        sweep.run_dask(
            fmu_path, TINY, client, progress=False, store=first, on_rows=interrupt_after_two_tasks
        )
    assert first.written == 4 and len(case_files(tmp_path)) == 4
    before = {p.name: (p.stat().st_ino, p.stat().st_mtime_ns) for p in tmp_path.glob("*deg*")}

    computed = []
    second = sweep.CaseStore(tmp_path, TINY)
    table = sweep.run_dask(
        fmu_path, TINY, client, progress=False, store=second, on_rows=computed.extend
    )
    assert second.written == len(computed) == total - 4  # only the missing cases ran
    assert {
        p.name: (p.stat().st_ino, p.stat().st_mtime_ns)
        for p in tmp_path.glob("*deg*")
        if p.name in before
    } == before  # not rewritten
    assert len(case_files(tmp_path)) == total
    pd.testing.assert_frame_equal(table, serial, check_exact=True)


def test_a_store_refuses_cases_of_other_settings_or_another_fmu(tmp_path):
    sweep.CaseStore(tmp_path / "a", TINY)
    with pytest.raises(sweep.SettingsMismatch, match="revolutions") as mismatch:
        sweep.CaseStore(tmp_path / "a", dataclasses.replace(TINY, revolutions=3))
    assert "steps_per_revolution" not in str(mismatch.value)  # only what differs
    one, other = tmp_path / "one.fmu", tmp_path / "other.fmu"
    one.write_bytes(b"one build")
    other.write_bytes(b"another build")
    sweep.CaseStore(tmp_path / "b", TINY, one)
    sweep.CaseStore(tmp_path / "b", TINY, one)  # the same FMU resumes
    with pytest.raises(sweep.SettingsMismatch, match="fmu_sha256"):
        sweep.CaseStore(tmp_path / "b", TINY, other)


def test_killing_a_worker_mid_sweep_loses_nothing_and_repeats_nothing(
    cluster, fmu_path, serial, tmp_path
):
    import pandas as pd

    client, workers = cluster
    assert len(client.scheduler_info()["workers"]) == 2
    groups = client.run(os.getpgid, 0)  # worker address -> its process group
    ours = {process.pid: process for process in workers}
    assert set(groups.values()) == set(ours)
    killed = {}

    def kill_a_busy_worker(rows):
        if killed:
            return
        busy = [address for address, keys in client.processing().items() if keys]
        assert busy, "no task in flight to lose"
        killed.update(address=busy[0], done=len(list(tmp_path.glob("*deg*"))))
        workers_process = ours[groups[busy[0]]]
        os.killpg(workers_process.pid, signal.SIGKILL)
        workers_process.wait(timeout=30)

    store = sweep.CaseStore(tmp_path, TINY)
    table = sweep.run_dask(
        fmu_path, TINY, client, progress=False, store=store, on_rows=kill_a_busy_worker
    )
    total = len(TINY.cases())
    assert 0 < killed["done"] < total  # killed in the middle
    assert killed["address"] not in client.scheduler_info()["workers"]
    assert store.written == total  # each case written once
    assert case_files(tmp_path) == sorted(f"{c.key}.json" for c in TINY.cases())  # no temp file
    assert not table.duplicated(["bend_angle_deg", "input_speed_rpm", "inertia_distribution"]).any()
    pd.testing.assert_frame_equal(table, serial, check_exact=True)
