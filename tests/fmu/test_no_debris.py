"""Runs leave nothing behind and say what ended them: a refused or damaged run
removes what it unzipped, SIGTERM and SIGHUP end a run as Ctrl-C does, and a
Ctrl-C inside an `FmuInstance` step reaches the host as KeyboardInterrupt."""

import os
import signal
import subprocess
import sys
import tempfile
import textwrap
import time
import zipfile
from pathlib import Path

import pytest
from conftest import ROOT, cardan_joint_here

from cardan_joint.host.fmu_info import BadFMUError
from cardan_joint.host.simulate import SimulationError, simulate

LONG = ("--stop-time", "1000", "--step", "1e-3")  # minutes of work: always interrupted


def _damaged(fmu_path, folder):
    """An FMU without its binary, and one whose binary fails its zip check."""
    without = folder / "without_binary.fmu"
    with zipfile.ZipFile(fmu_path) as source, zipfile.ZipFile(without, "w") as target:
        for item in source.infolist():
            if not item.filename.startswith("binaries/"):
                target.writestr(item, source.read(item))
    corrupt = folder / "corrupt.fmu"
    data = bytearray(fmu_path.read_bytes())
    with zipfile.ZipFile(fmu_path) as source:
        binary = next(i for i in source.infolist() if i.filename.startswith("binaries/"))
    middle = binary.header_offset + 30 + len(binary.filename) + binary.compress_size // 2
    data[middle] ^= 0xFF  # the binary's bytes no longer match their CRC
    corrupt.write_bytes(bytes(data))
    return without, corrupt


def test_ten_refused_or_damaged_runs_leave_no_folder_in_tmpdir(
    capsys, fmu_path, tmp_path, monkeypatch
):
    scratch = tmp_path / "tmpdir"
    scratch.mkdir()
    monkeypatch.setenv("TMPDIR", str(scratch))
    monkeypatch.setattr(tempfile, "tempdir", str(scratch))  # read once per process
    without, corrupt = _damaged(fmu_path, tmp_path)
    out = tmp_path / "out" / "run.csv"
    out.parent.mkdir()
    for _ in range(3):  # refused at the start, from Python and from the command
        with pytest.raises(SimulationError):
            simulate(fmu_path, stop_time=0.1, output_interval=1e-3, inputs={"bend_angle": 2.0})
        refused = cardan_joint_here(
            capsys, "simulate", "--fmu", fmu_path, "--set", "bend_angle=2", "--output", out
        )
        assert refused.returncode == 2, refused.stderr
    for damaged, named in ((without, "binaries/linux64/UniversalJoint.so is missing"),) * 2 + (
        (corrupt, "cannot unzip it"),
        (corrupt, "cannot unzip it"),
    ):
        with pytest.raises(BadFMUError, match=named):
            simulate(damaged, stop_time=0.1, output_interval=1e-3)
    assert list(scratch.iterdir()) == []
    run = cardan_joint_here(capsys, "simulate", "--fmu", without, "--output", out)
    assert run.returncode == 2 and "binaries/linux64/UniversalJoint.so is missing" in run.stderr
    assert list(scratch.iterdir()) == []


def _child(args, **options):
    """A child process in which SIGINT has Python's own handler (a shell may hand
    its background jobs SIGINT ignored)."""
    return subprocess.Popen(
        args,
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        preexec_fn=lambda: signal.signal(signal.SIGINT, signal.SIG_DFL),
        **options,
    )


def _said(args, **options) -> tuple[int, str]:
    """(the return code, what it wrote on either stream) of a `_child` that
    runs to its end."""
    process = _child(args, **options)
    try:
        out, err = process.communicate(timeout=30)
    finally:
        process.kill()
    return process.returncode, out.decode() + err.decode()


def _wait_for(stream, text: bytes) -> None:
    seen = b""
    while text not in seen:
        byte = stream.read(1)
        assert byte, f"the process ended before writing {text!r}: {seen!r}"
        seen += byte


@pytest.mark.parametrize("signum, status", [(signal.SIGTERM, 143), (signal.SIGHUP, 129)])
def test_sigterm_and_sighup_end_a_run_as_ctrl_c_does(fmu_path, tmp_path, signum, status):
    out, plot = tmp_path / "run.csv", tmp_path / "run.png"
    out.write_text("earlier run\n")
    plot.write_bytes(b"earlier plot")
    command = [sys.executable, "-m", "cardan_joint.cli", "simulate", "--fmu", str(fmu_path)]
    process = _child([*command, *LONG, "--output", str(out), "--progress"])
    try:
        _wait_for(process.stderr, b"simulate:")  # the progress bar: the FMU is stepping
        process.send_signal(signum)
        rest = process.communicate(timeout=60)[1].decode()
    finally:
        process.kill()
    name = signal.Signals(signum).name
    assert process.returncode == status, rest
    assert f"interrupted by {name} at t = " in rest and "no file written" in rest
    assert "Traceback" not in rest and "refused" not in rest
    assert out.read_text() == "earlier run\n" and plot.read_bytes() == b"earlier plot"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["run.csv", "run.png"]  # no .tmp


# A loop of steps whose 50th sends the signal from inside the FMU's own Python
# code (its model's step, entered with the step in Python), where a Ctrl-C
# landed most of the time; with the step in C, a timer sends it while C steps.
STEPPING = textwrap.dedent(
    """
    import os, sys, threading
    from cardan_joint.host.instance import FmuInstance, StepRefusedError

    with FmuInstance.open(sys.argv[1], start_values={"bend_angle": 0.3}) as joint:
        joint.set(input_speed=100.0)
        joint.step(1e-3)
        fmu = next(m for n, m in sys.modules.items() if n.endswith(".universal_joint.model"))
        calls = []
        if sys.argv[3] == "c":
            threading.Timer(0.3, os.kill, (os.getpid(), int(sys.argv[2]))).start()

        def signalling(method):
            def call(*args):
                calls.append(1)
                if len(calls) == 50:
                    os.kill(os.getpid(), int(sys.argv[2]))
                return method(*args)
            return call

        fmu.CardanJoint.run = signalling(fmu.CardanJoint.run)  # the slave's do_step runs it
        try:
            while True:
                joint.step(1e-3)
        except KeyboardInterrupt as interrupt:
            print(type(interrupt).__name__, flush=True)
            sys.exit(3)
        except StepRefusedError as refused:
            print("refused:", refused, flush=True)
            sys.exit(4)
    """
)


@pytest.mark.parametrize("step", ["python", "c"])
@pytest.mark.parametrize("signum", [signal.SIGINT, signal.SIGTERM])
def test_ctrl_c_in_an_instance_loop_raises_keyboard_interrupt(fmu_path, signum, step):
    python_step = {"CARDAN_JOINT_FMU_PYTHON_STEP": "1"} if step == "python" else {}
    code, said = _said(
        [sys.executable, "-c", STEPPING, str(fmu_path), str(int(signum)), step],
        env={**os.environ, **python_step},
    )
    assert code == 3, said
    expected = "KeyboardInterrupt" if signum == signal.SIGINT else "Stopped"
    assert said.strip() == expected


# Calls into an FmuInstance's FMU other than a step, with a Ctrl-C sent from
# where Python runs during the call: the slave's own Python (a get enters it to
# take the inputs and give the outputs; so does the end of initialization) or
# the logger's callback (the FMU says why a fixed parameter is not set), where
# ctypes would drop the interrupt.
CALLING = textwrap.dedent(
    """
    import os, signal, sys
    from cardan_joint.host.instance import FmuInstance

    class Signalling(list):  # the log sink: the logger's callback appends to it
        def append(self, message):
            super().append(message)
            os.kill(os.getpid(), signal.SIGINT)

    def signalling(method):
        def call(*args):
            os.kill(os.getpid(), signal.SIGINT)
            return method(*args)
        return call

    where = sys.argv[2]
    messages = Signalling() if where == "logger" else None
    with FmuInstance.open(sys.argv[1], messages=messages,
                          exit_initialization=where != "exit") as joint:
        core = next(m for n, m in sys.modules.items() if n.endswith(".fmi.core"))
        giving, ending = core.SlaveCore._current_outputs, core.SlaveCore.exit_initialization_mode
        if where == "slave":
            core.SlaveCore._current_outputs = signalling(giving)
        terminate = joint.fmu.terminate
        joint.fmu.terminate = lambda: print("terminated", flush=True) or terminate()
        try:
            if where == "slave":
                joint.values("output_speed")
            elif where == "exit":
                core.SlaveCore.exit_initialization_mode = signalling(ending)
                joint.exit_initialization_mode()
            else:
                joint.set(max_bend_angle=1.0)
            print("no interrupt", flush=True)
        except KeyboardInterrupt:
            print("KeyboardInterrupt", flush=True)
        core.SlaveCore._current_outputs = giving
        joint.set(input_speed=5.0)
        joint.step(1e-3)  # the call was not cut short: the instance goes on
        print(joint.values("input_speed")[0], flush=True)
    """
)


@pytest.mark.parametrize("where", ["slave", "logger", "exit"])
def test_ctrl_c_during_any_call_is_raised_after_it(fmu_path, where):
    """Held as a step's: the call completes, the interrupt is raised when it
    returns, and nothing is dropped or printed on the way; an instance whose
    initialization ended so is terminated when it closes."""
    code, said = _said([sys.executable, "-c", CALLING, str(fmu_path), where])
    assert code == 0, said
    # Only the end of initialization registers terminate after the patch.
    closed = ["terminated"] if where == "exit" else []
    assert said.split() == ["KeyboardInterrupt", "5.0", *closed], said


def _catches(pid: int, signum: int) -> bool:
    """Whether process `pid` has a handler of its own for `signum` (Linux)."""
    status = Path(f"/proc/{pid}/status").read_text()
    caught = next(line for line in status.splitlines() if line.startswith("SigCgt:"))
    return bool(int(caught.split()[1], 16) >> (signum - 1) & 1)


def test_ctrl_c_in_an_example_ends_it_in_one_line(fmu_path, tmp_path):
    example = [sys.executable, str(ROOT / "examples" / "driveshaft.py"), "--fmu", str(fmu_path)]
    process = _child([*example, "--revolutions", "100000", "--out", str(tmp_path)], cwd=ROOT)
    try:
        # SIGTERM caught: the example runs under run_example (Python catches SIGINT from its start).
        deadline = time.monotonic() + 60
        while not _catches(process.pid, signal.SIGTERM):
            assert process.poll() is None and time.monotonic() < deadline
            time.sleep(0.05)
        time.sleep(0.5)  # into its loop of steps
        process.send_signal(signal.SIGINT)
        err = process.communicate(timeout=60)[1].decode()
    finally:
        process.kill()
    assert process.returncode == 130, err
    assert err.strip() == "driveshaft.py: interrupted"
