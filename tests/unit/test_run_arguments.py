"""The one check of a run's arguments (host/run_arguments.py) and the files a
run writes whole or not at all (results.py): no FMU needed."""

import math
import signal
import tracemalloc

import numpy as np
import pytest

from cardan_joint import results
from cardan_joint.host import run_arguments
from cardan_joint.host.interrupts import interrupt_between_steps
from cardan_joint.host.run_arguments import RunTooLargeError, check_disk, check_memory, run_length
from cardan_joint.names import UsageError


@pytest.mark.parametrize(
    "stop_time, step, named",
    [
        (-1.0, 1e-3, "stop time -1.0 s"),
        (0.0, 1e-3, "stop time 0.0 s"),
        (math.nan, 1e-3, "stop time nan s"),
        (math.inf, 1e-3, "stop time inf s"),
        (1.0, 0.0, "(communication step) 0.0 s"),
        (1.0, -1e-3, "(communication step) -0.001 s"),
        (1.0, 2.0, "at most the stop time 1.0 s"),
        (1.0, math.nan, "(communication step) nan s"),
    ],
)
def test_a_run_length_that_cannot_run_is_refused_naming_the_value(stop_time, step, named):
    with pytest.raises(UsageError, match="must be") as error:
        run_length(stop_time, step)
    assert named in str(error.value)


def test_the_run_length_counts_steps_and_rows():
    length = run_length(1.0, 1e-3)
    assert (length.steps, length.rows) == (1000, 1001)
    assert run_length(1e9, 1e-3).steps == 10**12


def test_a_run_too_large_for_memory_names_its_size_before_it_starts():
    length = run_length(1e9, 1e-3)
    with pytest.raises(RunTooLargeError) as error:
        check_memory(length, 27, free=16e9)
    text = str(error.value)
    assert "1,000,000,000,000 steps" in text and "27 values" in text
    assert "PB of memory" in text and "16 GB available" in text
    check_memory(run_length(1.0, 1e-3), 27, free=16e9)  # a small run passes


def test_a_csv_too_large_for_the_disk_names_its_size(tmp_path):
    with pytest.raises(RunTooLargeError, match=r"about 675 TB as CSV .* 75 GB available"):
        check_disk(run_length(1e9, 1e-3), 27, tmp_path / "run.csv", free=75e9)
    check_disk(run_length(1.0, 1e-3), 27, tmp_path / "deeper" / "run.csv")  # measured: fits


def test_the_memory_estimate_covers_fmpys_recorded_rows():
    """FMPy records a tuple of floats per row, then copies them into an array:
    the estimate per row bounds what that takes, within a factor 2."""
    values, rows = 27, 20_000
    tracemalloc.start()
    try:
        recorded = [tuple(float(i + j) + 0.5 for j in range(values)) for i in range(rows)]
        array = np.array(recorded, dtype=[(f"v{j}", float) for j in range(values)])
        _, peak = tracemalloc.get_traced_memory()
    finally:
        tracemalloc.stop()
    assert len(array) == rows
    estimate = rows * (run_arguments.ROW_BYTES + run_arguments.VALUE_BYTES * values)
    assert peak <= estimate <= 2 * peak


def test_a_csv_stream_writes_fmpys_bytes(tmp_path):
    from fmpy.util import write_csv as fmpy_write_csv

    rng = np.random.default_rng(2)
    data = results.structured(
        {
            "time": np.sort(rng.random(300)),
            "x": rng.standard_normal(300) * 10.0 ** rng.integers(-300, 300, 300),
            "y": [1e16, 1e-5, -0.0, 5e-324, 0.1, math.inf] * 50,
        }
    )
    fmpy_write_csv(str(tmp_path / "fmpy.csv"), data)
    with results.CsvStream(tmp_path / "ours.csv", data.dtype.names) as stream:
        for chunk in np.array_split(data, 7):
            stream.write(chunk)
    assert (tmp_path / "ours.csv").read_bytes() == (tmp_path / "fmpy.csv").read_bytes()


def test_a_file_interrupted_while_written_leaves_the_earlier_one(tmp_path):
    path = tmp_path / "run.csv"
    path.write_text("earlier\n")
    data = results.structured({"time": [0.0, 1.0], "x": [1.0, 2.0]})
    with pytest.raises(KeyboardInterrupt):
        with results.CsvStream(path, data.dtype.names) as stream:
            stream.write(data)
            raise KeyboardInterrupt
    with pytest.raises(KeyboardInterrupt):
        with results.replaced_whole(path) as temporary:
            temporary.write_text("half")
            raise KeyboardInterrupt
    assert path.read_text() == "earlier\n"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["run.csv"]  # no temporary left
    results.write_csv(data, path)
    assert results.read_csv(path)["x"].tolist() == [1.0, 2.0]


def test_ctrl_c_during_a_run_is_held_for_the_step_boundary():
    import os

    assert signal.getsignal(signal.SIGINT) is signal.default_int_handler
    with interrupt_between_steps() as request:
        os.kill(os.getpid(), signal.SIGINT)  # delivered now: recorded, not raised
        assert request.requested
        with pytest.raises(KeyboardInterrupt):  # a second one does not wait
            os.kill(os.getpid(), signal.SIGINT)
    assert signal.getsignal(signal.SIGINT) is signal.default_int_handler


def test_a_handler_the_host_installed_is_left_alone():
    seen = []
    previous = signal.signal(signal.SIGINT, lambda *_: seen.append(1))
    try:
        with interrupt_between_steps() as request:
            import os

            os.kill(os.getpid(), signal.SIGINT)
        assert seen == [1] and not request.requested
    finally:
        signal.signal(signal.SIGINT, previous)


@pytest.mark.parametrize("signum", [signal.SIGTERM, signal.SIGHUP])
def test_sigterm_and_sighup_are_held_like_ctrl_c_and_restored(signum):
    import os

    from cardan_joint.host.interrupts import Stopped

    assert signal.getsignal(signum) is signal.SIG_DFL
    with interrupt_between_steps() as request:
        os.kill(os.getpid(), signum)  # recorded, not the end of the process
        assert request.signum == signum
        with pytest.raises(Stopped) as second:  # a second one does not wait
            os.kill(os.getpid(), signum)
        assert second.value.signum == signum
    assert signal.getsignal(signum) is signal.SIG_DFL


def test_an_instance_holds_a_signal_to_the_end_of_its_step_only():
    import os

    from cardan_joint.host.interrupts import STEP_INTERRUPTS

    STEP_INTERRUPTS.acquire()
    STEP_INTERRUPTS.acquire()  # two instances open
    try:
        held = STEP_INTERRUPTS.request
        with pytest.raises(KeyboardInterrupt):  # between steps: at once
            os.kill(os.getpid(), signal.SIGINT)
        held.holding = True  # in a step
        os.kill(os.getpid(), signal.SIGINT)
        held.holding = False
        with pytest.raises(KeyboardInterrupt):  # after it
            held.raise_requested()
        held.raise_requested()  # once
        STEP_INTERRUPTS.release()
        assert signal.getsignal(signal.SIGINT) is not signal.default_int_handler
    finally:
        STEP_INTERRUPTS.release()
    assert signal.getsignal(signal.SIGINT) is signal.default_int_handler
    assert signal.getsignal(signal.SIGTERM) is signal.SIG_DFL


def test_the_command_prints_its_version(capsys):
    from cardan_joint import __version__, cli

    with pytest.raises(SystemExit) as exit:
        cli.main(["--version"])
    assert exit.value.code == 0
    assert capsys.readouterr().out == f"cardan-joint {__version__}\n"
