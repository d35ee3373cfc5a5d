"""Issue 24 item 2: any one resources file of an FMU emptied, truncated, missing or
contradicting the others: instantiate returns NULL, a logger message names the file,
the C host exits normally; under valgrind, no invalid read or write in the FMU's
code. FMI 2.0 and 3.0."""

import os
import re
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

ENVIRONMENT = {"PATH": "/usr/bin:/bin"}


def empty(path: Path) -> None:
    path.write_bytes(b"")


def truncated(path: Path) -> None:
    data = path.read_bytes()
    path.write_bytes(data[: len(data) // 2])


def missing(path: Path) -> None:
    path.unlink()


def another_module(path: Path) -> None:
    path.write_text("no_such_slave_module\n")


def another_size(path: Path) -> None:
    """The first multi-value variable (FMI 3.0's quaternion) said to hold one value,
    or (FMI 2.0) an output said to be a fixed parameter: the record contradicts the
    slave."""
    lines = path.read_text().splitlines()
    for k, line in enumerate(lines):
        fields = line.split()
        if line.startswith("#"):
            continue
        if fields[2] != "1":
            fields[2] = "1"
            lines[k] = " ".join(fields)
            break
    else:
        fields = lines[-1].split()
        fields[3] = "1"
        lines[-1] = " ".join(fields)
    path.write_text("\n".join(lines) + "\n")


def another_time(path: Path) -> None:
    """A second `time` row: FMI 3.0's own again (value references 1-based, time
    first), or in FMI 2.0 one beyond the slave's value references."""
    rows = [line for line in path.read_text().splitlines() if not line.startswith("#")]
    own = next((row for row in rows if row.endswith(" time")), None)
    path.write_text(path.read_text() + (own or "999 Real 1 0 time") + "\n")


def time_at_zero(path: Path) -> None:
    """FMI 3.0's `time` at value reference 0 (the numbering before 1-based positions),
    or in FMI 2.0 a `time` row there: 0 names no variable of the slave."""
    text = path.read_text()
    if "\n1 Float64 1 0 time\n" in text:
        path.write_text(text.replace("\n1 Float64 1 0 time\n", "\n0 Float64 1 0 time\n"))
    else:
        path.write_text(text + "0 Real 1 0 time\n")


def newer_python(path: Path) -> None:
    path.write_text(path.read_text().replace("minimum = 3.10", "minimum = 3.99"))


CASES = {
    "slavemodule.txt": [empty, missing, another_module],
    "variables.txt": [empty, truncated, missing, another_size, another_time, time_at_zero],
    "python_runtime.txt": [empty, truncated, missing, newer_python],
}
PARAMETERS = [
    (version, name, damage)
    for version in (2, 3)
    for name, damages in CASES.items()
    for damage in damages
]


def damaged_copy(request, tmp_path, version, name, damage) -> tuple:
    host = request.getfixturevalue("c_host3" if version == 3 else "c_host")
    unzipped = request.getfixturevalue("fmi3_unzipped" if version == 3 else "unzipped_fmu")
    copy = tmp_path / "fmu"
    shutil.copytree(unzipped, copy)
    damage(copy / "resources" / name)
    return host, copy


@pytest.mark.parametrize(
    "version, name, damage",
    PARAMETERS,
    ids=[f"fmi{v}-{n}-{d.__name__}" for v, n, d in PARAMETERS],
)
def test_a_damaged_resources_file_is_a_null_instance_naming_it(
    request, tmp_path, version, name, damage
):
    host, copy = damaged_copy(request, tmp_path, version, name, damage)
    run = subprocess.run(
        [str(host), "instantiate", str(copy)],
        env=ENVIRONMENT,
        capture_output=True,
        text=True,
        timeout=120,
    )
    assert run.returncode == 0, run.stdout + run.stderr
    assert "instance NULL" in run.stdout, run.stdout + run.stderr
    assert name in run.stderr and "LOG 3" in run.stderr, run.stderr


# Under valgrind: the quickest case here, in the developer's loop; the other three
# (VALGRIND_SLOW, 5-25 s each under valgrind) in tests/system/test_long_runs.py.
VALGRIND = [(3, "slavemodule.txt", another_module)]
VALGRIND_SLOW = [
    (2, "slavemodule.txt", empty),
    (2, "variables.txt", truncated),
    (3, "variables.txt", another_size),
]
needs_valgrind = pytest.mark.skipif(not shutil.which("valgrind"), reason="needs valgrind")


@needs_valgrind
@pytest.mark.parametrize(
    "version, name, damage", VALGRIND, ids=[f"fmi{v}-{n}-{d.__name__}" for v, n, d in VALGRIND]
)
def test_under_valgrind_no_invalid_access_in_the_fmus_code(
    request, tmp_path, version, name, damage
):
    no_invalid_access_under_valgrind(request, tmp_path, version, name, damage)


def no_invalid_access_under_valgrind(request, tmp_path, version, name, damage) -> None:
    """The damaged copy instantiated in the C host under valgrind: a NULL instance
    and no invalid read or write in the FMU's code."""
    host, copy = damaged_copy(request, tmp_path, version, name, damage)
    run = subprocess.run(
        ["valgrind", "--error-limit=no", str(host), "instantiate", str(copy)],
        env=ENVIRONMENT,
        capture_output=True,
        text=True,
        timeout=600,
    )
    assert run.returncode == 0 and "instance NULL" in run.stdout, run.stdout + run.stderr
    # Each error block: "Invalid read/write ..." then its stack; CPython's own
    # (unsuppressed) reports are not the FMU's.
    blocks = re.split(r"==\d+== \n", run.stderr)
    ours = [
        block
        for block in blocks
        if re.search(r"Invalid (read|write)", block) and "UniversalJoint" in block
    ]
    assert not ours, ours[0]
    assert "ERROR SUMMARY" in run.stderr


# Patches at the end of the slave module's file, for its class: no fast path
# (so every read and write reaches the slave), and a getter with one value too many.
NO_FAST_PATH = """
def _no_layout(cls):
    raise RuntimeError("no fast path")

{cls}.fast_layout = classmethod(_no_layout)
"""
ONE_TOO_MANY = """
def _one_too_many(getter):
    return lambda self, vrs: list(getter(self, vrs)) + [0.0]

{cls}.{getter} = _one_too_many({cls}.{getter})
"""
READ_ONE_OUTPUT = """
import sys
from fmpy import read_model_description
from fmpy.fmi1 import FMICallException
from fmpy.fmi2 import FMU2Slave
from fmpy.fmi3 import FMU3Slave
folder, getter = sys.argv[1:]
description = read_model_description(folder)
kind = FMU3Slave if description.fmiVersion.startswith("3") else FMU2Slave
fmu = kind(guid=description.guid, unzipDirectory=folder, instanceName="counted",
           modelIdentifier=description.coSimulation.modelIdentifier)
fmu.instantiate()
vr = next(v.valueReference for v in description.modelVariables if v.name == "output_speed")
try:
    print("read", getattr(fmu, getter)([vr]))
except FMICallException as refused:
    print("refused", refused.status)
"""


def patched_copy(request, tmp_path, version, *patches, **names) -> Path:
    """A copy of the FMU whose slave module ends with `patches` (formatted with its
    class's name and `names`)."""
    unzipped = request.getfixturevalue("fmi3_unzipped" if version == 3 else "unzipped_fmu")
    copy = tmp_path / "fmu"
    shutil.copytree(unzipped, copy)
    resources = copy / "resources"
    script = resources / f"{(resources / 'slavemodule.txt').read_text().strip()}.py"
    cls = re.search(r"^class (\w+)\(", script.read_text(), re.MULTILINE).group(1)
    script.write_text(script.read_text() + "".join(p.format(cls=cls, **names) for p in patches))
    return copy


def read_one_output(copy: Path, getter: str) -> tuple:
    """FMPy's `getter` of output_speed: its last line ("read [...]" or "refused
    <status>"; FMPy's FMI 3.0 logger prints on stdout before it) and stderr."""
    run = subprocess.run(
        [sys.executable, "-c", READ_ONE_OUTPUT, str(copy), getter],
        env={**os.environ, "CARDAN_JOINT_FMU_STDERR": "1"},
        capture_output=True,
        text=True,
        timeout=120,
    )
    assert run.returncode == 0, run.stderr
    return run.stdout.splitlines()[-1], run.stderr


@pytest.mark.parametrize("version", [2, 3])
def test_a_getter_answering_another_count_is_refused_not_copied(request, tmp_path, version):
    """The runtime copies a getter's values into the host's array only when the
    slave gave exactly as many as the host asked for (slave_values.c)."""
    getter = "get_float64" if version == 3 else "get_real"
    copy = patched_copy(request, tmp_path, version, NO_FAST_PATH, ONE_TOO_MANY, getter=getter)
    answer, messages = read_one_output(copy, "getFloat64" if version == 3 else "getReal")
    assert answer == "refused 4"  # fmi2Fatal / fmi3Fatal
    assert f"the slave's {getter} gave 2 values (-1: no list) for 1 values" in messages


def test_a_record_naming_another_type_is_no_way_past_the_float64_slave(request, tmp_path):
    """FMI 3.0: a variable record that gives a variable another type than the
    slave's (caught at instantiate when the slave has the fast path) still
    reaches no accessor of that type: the call is refused by name (fmi3_calls.c)."""
    copy = patched_copy(request, tmp_path, 3, NO_FAST_PATH)
    record = copy / "resources" / "variables.txt"
    record.write_text(re.sub(r"Float64( 1 0 output_speed)", r"Int32\1", record.read_text()))
    answer, messages = read_one_output(copy, "getInt32")
    assert answer == "refused 3"  # fmi3Error
    assert "fmi3GetInt32: the slave has Float64 variables only" in messages
