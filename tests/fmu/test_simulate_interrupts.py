"""Ctrl-C during `cardan-joint simulate`, sent for real (SIGINT to the running
command) at several moments: exit 130, "interrupted at t = ... s", the FMU not
blamed, and no file half written (an earlier file of the name left as it was)."""

import os
import signal
import subprocess
import sys
import textwrap
import time

import numpy as np
import pytest

from cardan_joint import results
from cardan_joint.host.interrupts import SimulationInterrupted
from cardan_joint.host.simulate import simulate

LONG = ("--stop-time", "1000", "--step", "1e-3")  # minutes of work: always interrupted


def _earlier(tmp_path):
    out, plot = tmp_path / "run.csv", tmp_path / "run.png"
    out.write_text("earlier run\n")
    plot.write_bytes(b"earlier plot")
    return out, plot


def _untouched(tmp_path, out, plot):
    assert out.read_text() == "earlier run\n" and plot.read_bytes() == b"earlier plot"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["run.csv", "run.png"]  # no temporary


def _started(process) -> None:
    """Wait for the run's progress bar: the FMU is stepping."""
    seen = b""
    while b"simulate:" not in seen:
        byte = process.stderr.read(1)
        assert byte, "the command ended before its run started"
        seen += byte


@pytest.mark.parametrize("delay", [0.0, 0.3, 1.5])
def test_ctrl_c_during_the_run_exits_130_and_writes_nothing(fmu_path, tmp_path, delay):
    out, plot = _earlier(tmp_path)
    command = [sys.executable, "-m", "cardan_joint.cli", "simulate", "--fmu", str(fmu_path)]
    process = subprocess.Popen(
        [*command, *LONG, "--output", str(out), "--progress"], stderr=subprocess.PIPE
    )
    try:
        _started(process)
        time.sleep(delay)
        process.send_signal(signal.SIGINT)
        rest = process.communicate(timeout=60)[1].decode()
    finally:
        process.kill()
    assert process.returncode == 130, rest
    assert "interrupted at t = " in rest and "of 1000 s: no file written" in rest
    assert "refused" not in rest and "the slave's" not in rest and "Traceback" not in rest
    _untouched(tmp_path, out, plot)


# The command in a process that sends itself SIGINT at one exact moment of writing.
SELF_INTERRUPTING = textwrap.dedent(
    """
    import os, signal, sys
    from cardan_joint import cli, results
    from cardan_joint.host import plotting
    where, calls = sys.argv[1], []

    def interrupting(original):
        def call(*args, **kwargs):
            calls.append(1)
            if len(calls) == 2 or where != "write":
                os.kill(os.getpid(), signal.SIGINT)
            return original(*args, **kwargs)
        return call

    target = {"write": results.CsvStream, "commit": results.CsvStream, "plot": plotting}[where]
    name = {"write": "write", "commit": "commit", "plot": "save_figure"}[where]
    setattr(target, name, interrupting(getattr(target, name)))
    sys.exit(cli.main(sys.argv[2:]))
    """
)


@pytest.mark.parametrize(
    "where, said",
    [
        ("write", "interrupted at t = "),  # a chunk written during the run: held to the step
        ("commit", "interrupted while writing"),  # the run over, its file being completed
    ],
)
def test_ctrl_c_while_the_csv_is_written_leaves_no_truncated_file(fmu_path, tmp_path, where, said):
    out, plot = _earlier(tmp_path)
    run = subprocess.run(
        [sys.executable, "-c", SELF_INTERRUPTING, where, "simulate", "--fmu", str(fmu_path)]
        + ["--stop-time", "20", "--output", str(out), "--no-progress"],
        capture_output=True,
        text=True,
        timeout=300,
    )
    assert run.returncode == 130, run.stderr
    assert said in run.stderr and "no file written" in run.stderr
    assert "Traceback" not in run.stderr
    _untouched(tmp_path, out, plot)


def test_ctrl_c_while_the_plot_is_drawn_keeps_the_whole_csv(fmu_path, tmp_path):
    out, plot = _earlier(tmp_path)
    run = subprocess.run(
        [sys.executable, "-c", SELF_INTERRUPTING, "plot", "simulate", "--fmu", str(fmu_path)]
        + ["--stop-time", "0.5", "--output", str(out), "--no-progress"],
        capture_output=True,
        text=True,
        timeout=300,
    )
    assert run.returncode == 130 and "interrupted while drawing" in run.stderr, run.stderr
    assert len(results.read_csv(out)) == 501  # whole
    assert plot.read_bytes() == b"earlier plot"


def test_simulate_raises_an_interrupt_at_a_step_boundary_not_a_refusal(fmu_path):
    def interrupt_at(time, recorder):
        if time >= 0.05 - 1e-12:
            os.kill(os.getpid(), signal.SIGINT)
        return True

    with pytest.raises(SimulationInterrupted) as interrupted:
        simulate(fmu_path, stop_time=10.0, output_interval=1e-3, step_finished=interrupt_at)
    assert interrupted.value.time == pytest.approx(0.05)
    assert str(interrupted.value) == "interrupted at t = 0.05 s"
    rows = interrupted.value.result
    assert rows["time"][-1] == pytest.approx(0.05) and np.all(np.diff(rows["time"]) > 0)
    assert signal.getsignal(signal.SIGINT) is signal.default_int_handler


@pytest.mark.parametrize(
    "stop, status, said",
    [(signal.SIGINT, 130, "interrupted: "), (signal.SIGTERM, 143, "interrupted by SIGTERM: ")],
)
def test_a_stop_signal_during_a_sweep_keeps_the_finished_cases(
    fmu_path, tmp_path, stop, status, said
):
    command = [
        sys.executable,
        "-m",
        "cardan_joint.cli",
        "sweep",
        "--serial",
        "--fmu",
        str(fmu_path),
    ]
    grid = ["--bend-angles", "5", "10", "15", "20", "--speeds", "1000", "2000", "3000"]
    # Cases long enough that the sweep is still running when the signal lands,
    # however loaded the machine that reads its progress bar.
    grid += ["--revolutions", "20"]
    process = subprocess.Popen(
        [*command, *grid, "--out", str(tmp_path), "--progress"], stderr=subprocess.PIPE
    )
    try:
        seen = b""
        while b" 4/48 [" not in seen:  # the progress bar after the first task: cases stored
            byte = process.stderr.read(1)
            assert byte, seen.decode()
            seen += byte
        process.send_signal(stop)
        rest = process.communicate(timeout=60)[1].decode()
    finally:
        process.kill()
    assert process.returncode == status and "Traceback" not in rest, rest
    assert said in rest and "run it again (without --fresh)" in rest
    kept = list((tmp_path / "sweep.cases").glob("*deg_*rpm_*.json"))
    assert 0 < len(kept) < 48 and not (tmp_path / "sweep.csv").exists()
