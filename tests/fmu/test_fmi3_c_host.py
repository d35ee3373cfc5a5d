"""The FMI 3.0 FMU in a C host, loaded as an FMI tool loads it: dlopen RTLD_LOCAL,
empty environment, no Python of its own (tests/c_host/host3.c, compiled here with cc)."""

import ctypes
import re
import shutil
import subprocess
import sys
import zipfile
from pathlib import Path

import numpy as np
import pytest
from test_c_host import EMPTY_ENVIRONMENT, run_host

from cardan_joint.fmi.native import fmi3_headers


def broken_copy(fmi3_unzipped, tmp_path, break_it) -> Path:
    copy = tmp_path / "fmu"
    shutil.copytree(fmi3_unzipped, copy)
    break_it(copy / "resources")
    return copy


def test_c_host_equals_fmpy_over_ten_thousand_steps(c_host3, fmi3_path, fmi3_unzipped):
    from fmpy import simulate_fmu

    steps, dt = 10_000, 1e-3
    settings = {
        "input_speed": 40.0,
        "input_acceleration": 3.0,
        "bend_angle": 0.4,
        "bend_angle_rate": 0.01,
        "load_torque": 50.0,
        "yoke_phase": 0.3,
    }
    run = run_host(
        c_host3, "run", fmi3_unzipped, steps, dt, *(f"{n}={v!r}" for n, v in settings.items())
    )
    names = run.stdout.splitlines()[0].replace('"', "").split(",")
    ours = np.loadtxt(run.stdout.splitlines()[1:], delimiter=",")
    theirs = simulate_fmu(
        str(fmi3_path), stop_time=steps * dt, output_interval=dt, start_values=settings
    )
    assert ours.shape == (len(theirs), len(names)) and len(theirs) == steps + 1
    assert "crosspiece_quaternion[4]" in names  # arrays come element by element
    for column, name in enumerate(names):
        array = re.fullmatch(r"(\w+)\[(\d+)\]", name)
        expected = theirs[array[1]][:, int(array[2]) - 1] if array else theirs[name]
        np.testing.assert_allclose(ours[:, column], expected, rtol=1e-12, atol=0, err_msg=name)


def test_a_bad_input_with_logging_off_reaches_the_logger_once(c_host3, fmi3_unzipped):
    run = run_host(c_host3, "bad", fmi3_unzipped, "bend_angle", "2.0")
    assert "set 0 step 3 logger_calls 1" in run.stdout  # a refused step: fmi3Error, one message
    assert "bend_angle = 2.0 rad" in run.stdout and "max_bend_angle" in run.stdout
    assert "t = 0.0 s" in run.stdout
    assert "[UniversalJoint" not in run.stderr  # nothing on stderr


# name -> (status, logger calls, what the message says); pythonfmu3 alone would
# abort the host on fmi3GetFloat32 and fmi3GetClock, return OK on the counts and
# take any pointer for a Python object.
MISUSE = {
    "model_exchange": (3, 1, "co-simulation only"),
    "step_before_init": (3, 1, "fmi3DoStep is not allowed before initialization"),
    "exit_before_enter": (3, 1, "fmi3ExitInitializationMode is not allowed before"),
    "enter_twice": (3, 1, "fmi3EnterInitializationMode is not allowed in step mode"),
    "get_float32": (3, 1, "value reference 2 (input_speed, Float64) is of another type"),
    "get_float32_none": (0, 0, ""),
    "get_clock": (3, 1, "fmi3GetClock is not supported: the FMU has no clocks"),
    "event_mode": (3, 1, "fmi3EnterEventMode is not supported"),
    "update_discrete": (3, 1, "fmi3UpdateDiscreteStates is not supported"),
    "directional": (3, 1, "fmi3GetDirectionalDerivative is not supported"),
    "short_count": (3, 1, "nValues is 4 but the 2 value references hold 5 values"),
    "long_count": (3, 1, "nValues is 6 but the 2 value references hold 5 values"),
    "unknown_reference": (3, 1, "value reference 999 is not a variable of this FMU"),
    "null_values": (3, 1, "fmi3GetFloat64 got a NULL array"),
    "right_count": (0, 0, ""),
    "step_null_results": (3, 1, "fmi3DoStep got a NULL pointer"),
    "step": (0, 0, ""),
    "get_state": (0, 0, ""),
    "set_foreign_state": (3, 1, "which this instance did not create or has already freed"),
    "serialize_short": (3, 1, "ask fmi3SerializedFMUStateSize first"),
    "serialize_long": (0, 0, ""),  # pythonfmu3 alone reads past the state's bytes
    "free_state": (0, 0, ""),
    "set_freed_state": (3, 1, "which this instance did not create or has already freed"),
    "free_again": (3, 1, "which this instance did not create or has already freed"),
    "step_after_terminate": (3, 1, "not allowed after fmi3Terminate"),
    "reset": (0, 0, ""),
    "step_after_reset": (0, 0, ""),
}


def test_unsupported_calls_wrong_counts_and_call_order_are_errors_with_a_message(
    c_host3, fmi3_unzipped
):
    run = run_host(c_host3, "misuse", fmi3_unzipped)
    answers = {}
    for line in run.stdout.splitlines():
        head, message = line.split(" | ")
        name, status, calls = head.split()
        answers[name] = (int(status), int(calls), message)
    assert answers.keys() == MISUSE.keys()
    for name, (status, calls, message) in MISUSE.items():
        assert answers[name][:2] == (status, calls), (name, answers[name])
        assert message in answers[name][2], (name, answers[name])


@pytest.mark.parametrize(
    "break_it, says",
    [
        (
            lambda resources: (
                (resources / (resources / "slavemodule.txt").read_text().strip())
                .with_suffix(".py")
                .open("a")
                .write("\nraise ImportError('broken on purpose')\n")
            ),
            "does not import from",
        ),
        (lambda resources: (resources / "python_runtime.txt").unlink(), "python_runtime.txt"),
        (lambda resources: (resources / "variables.txt").unlink(), "variables.txt"),
        (lambda resources: (resources / "slavemodule.txt").unlink(), "slavemodule.txt"),
    ],
    ids=["slave code cannot import", "no runtime record", "no variables", "no module name"],
)
def test_a_broken_fmu_gives_null_and_a_message_and_the_host_lives(
    c_host3, fmi3_unzipped, tmp_path, break_it, says
):
    run = run_host(c_host3, "instantiate", broken_copy(fmi3_unzipped, tmp_path, break_it))
    assert "instance NULL logger_calls 1" in run.stdout
    assert says in run.stderr and "LOG 3" in run.stderr


def test_two_instances_on_two_threads_and_one_on_two_in_turn_equal_one_alone(
    c_host3, fmi3_unzipped
):
    assert "threads ok" in run_host(c_host3, "threads", fmi3_unzipped, 2000).stdout


def test_two_hundred_instantiate_free_cycles_and_a_clean_exit(c_host3, fmi3_unzipped):
    assert "cycles 200 ok" in run_host(c_host3, "cycles", fmi3_unzipped, 200).stdout


def test_call_order_fuzz_every_illegal_call_answered(c_host3, fmi3_unzipped):
    run = run_host(c_host3, "fuzz", fmi3_unzipped, 20261123, 10_000)
    assert "fuzz 10000 calls" in run.stdout
    assert "all answered; after reset equal to a fresh instance" in run.stdout


def test_every_fmi3_function_of_the_standard_is_the_loaders(fmi3_unzipped):
    declared = re.findall(
        r"FMI3_Export\s+fmi3\w+TYPE\s+(fmi3\w+);", (fmi3_headers() / "fmi3Functions.h").read_text()
    )
    assert len(declared) == 75  # FMI 3.0's whole API
    # Loading runs nothing: the loader starts Python and pythonfmu3 at instantiate.
    loader = ctypes.CDLL(str(Path(fmi3_unzipped, "binaries/x86_64-linux/UniversalJoint.so")))
    assert [name for name in declared if not hasattr(loader, name)] == []


def test_fmpy_in_a_python_that_links_libpython_statically(fmi3_path):
    """/usr/bin/python3.11 has libpython in its executable: the loader must use it."""
    python = Path("/usr/bin/python3.11")
    if not python.exists() or sys.version_info[:2] != (3, 11):
        pytest.skip("needs /usr/bin/python3.11 and a 3.11 build")
    site = next(p for p in sys.path if p.endswith("site-packages"))
    script = (
        "from fmpy import simulate_fmu\n"
        f"r = simulate_fmu({str(fmi3_path)!r}, stop_time=0.5, output_interval=1e-3,"
        " start_values={'input_speed': 12.0, 'bend_angle': 0.4})\n"
        "print(repr(float(r['output_angle'][-1])), repr(float(r['crosspiece_torque'][-1, 2])))\n"
    )
    runs = [
        subprocess.run(
            [executable, "-c", script],
            capture_output=True,
            text=True,
            env={**EMPTY_ENVIRONMENT, "PYTHONPATH": site},
            timeout=120,
        )
        for executable in (str(python), sys.executable)
    ]
    assert all(run.returncode == 0 for run in runs), runs[0].stderr + runs[1].stderr
    assert runs[0].stdout == runs[1].stdout and runs[0].stdout  # bit for bit


def test_the_fmu_ships_the_runtime_as_its_only_binary(fmi3_path):
    names = set(zipfile.ZipFile(fmi3_path).namelist())
    assert {
        "binaries/x86_64-linux/UniversalJoint.so",
        "resources/python_runtime.txt",
        "resources/variables.txt",
    } <= names
    assert [name for name in names if name.startswith("binaries/")] == [
        "binaries/x86_64-linux/UniversalJoint.so"
    ]
