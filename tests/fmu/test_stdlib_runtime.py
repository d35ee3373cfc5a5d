"""Issue 18, item 2: the FMU's Python code runs on the standard library alone.

Every model's slave is stepped in a process that refuses numpy (as a host's
Python without it would) and must give the values of an ordinary run bit for
bit; the built FMUs, run by FMPy, give those same values.
"""

import json
import subprocess
import sys
from pathlib import Path

import pytest
from runtime_driver import INPUTS, STEP_SIZE, STEPS

from cardan_joint.host.instance import FmuInstance

DRIVER = Path(__file__).resolve().parents[1] / "runtime_driver.py"


def driver_run(*args: str) -> dict:
    run = subprocess.run(
        [sys.executable, str(DRIVER), *args], capture_output=True, text=True, timeout=300
    )
    assert run.returncode == 0, run.stderr
    return json.loads(run.stdout)


@pytest.fixture(scope="module")
def without_numpy() -> dict:
    return driver_run("--no-numpy")


def test_every_model_imports_and_steps_without_numpy_as_with_it(without_numpy):
    assert without_numpy.pop("numpy_imported") is False
    ordinary = driver_run()
    ordinary.pop("numpy_imported")
    assert set(ordinary) == set(INPUTS)
    for name, run in ordinary.items():
        assert len(run["rows"]) == STEPS + 1
        # json keeps every float exactly (repr), so equality is bit for bit.
        assert without_numpy[name] == run, name


@pytest.mark.parametrize(
    ("fixture", "model"), [("fmu_path", "UniversalJoint"), ("fmi3_scalar_path", "UniversalJoint3")]
)
def test_the_built_fmu_in_fmpy_gives_the_values_of_the_standard_library_run(
    request, without_numpy, fixture, model
):
    expected = without_numpy[model]
    with FmuInstance.open(request.getfixturevalue(fixture)) as joint:
        refs = [joint.references[name] for name in expected["names"]]
        size = sum(joint.sizes[name] for name in expected["names"])

        def values():
            if joint.fmi3:
                return joint.fmu.getFloat64(refs, size)
            return joint.fmu.getReal(refs)

        rows = [values()]
        inputs = INPUTS[model]
        for step in range(STEPS):
            joint.set(**inputs)
            joint.fmu.doStep(step * STEP_SIZE, STEP_SIZE)
            rows.append(values())
    assert rows == expected["rows"]
