"""Issue 4: bad input is refused with a clear message and loses nothing;
parameters stay fixed."""

import math
import subprocess
import sys
import zipfile

import numpy as np
import pytest
from robustness_support import GOOD, REFUSED, all_reals

from cardan_joint.host.instance import FmuInstance
from cardan_joint.host.simulate import SimulationError, simulate
from cardan_joint.models.universal_joint import variables as table
from cardan_joint.models.universal_joint.model import CardanJoint

GUARD = table.BY_NAME["max_bend_angle"].start

BAD_INPUTS = {
    "bend angle at the guard": (dict(bend_angle=GUARD), 0.01, ["bend_angle", "max_bend_angle"]),
    "bend angle beyond the guard": (
        dict(bend_angle=-1.5),
        0.01,
        ["bend_angle = -1.5", "max_bend_angle"],
    ),
    "bend rate reaching the guard within the step": (
        dict(bend_angle=1.3, bend_angle_rate=20.0),
        0.01,
        ["bend_angle", "bend_angle_rate = 20.0", "max_bend_angle"],
    ),
    "NaN input speed": (dict(input_speed=math.nan), 0.01, ["input_speed = nan", "finite"]),
    "infinite input acceleration": (
        dict(input_acceleration=math.inf),
        0.01,
        ["input_acceleration = inf"],
    ),
    "NaN bend angle rate": (dict(bend_angle_rate=math.nan), 0.01, ["bend_angle_rate = nan"]),
    "infinite load torque": (dict(load_torque=-math.inf), 0.01, ["load_torque = -inf"]),
    "negative step": ({}, -0.01, ["step size = -0.01", "> 0"]),
    "zero step": ({}, 0.0, ["step size = 0.0", "> 0"]),
    "NaN step": ({}, math.nan, ["step size = nan"]),
    "speed beyond its physical range": (
        dict(input_speed=1e308),
        0.01,
        ["input_speed = 1e+308", "outside its range", "100000.0"],
    ),
    "step overflowing the input angle": (
        dict(bend_angle_rate=0.0, bend_angle_acceleration=0.0),
        1e305,
        ["input_speed = ", "overflows", "rad per step"],
    ),
}


@pytest.mark.parametrize("case", BAD_INPUTS)
def test_bad_input_is_refused_named_and_loses_nothing(model_description, unzipped_fmu, case):
    bad, step, expected_words = BAD_INPUTS[case]
    messages = []
    joint = FmuInstance(model_description, unzipped_fmu, name="victim", messages=messages)
    twin = FmuInstance(model_description, unzipped_fmu, name="twin")
    try:
        for j in (joint, twin):
            j.set(**GOOD)
            for _ in range(5):
                j.step(0.01)
        before = all_reals(joint)
        joint.set(**bad)
        assert joint.try_step(step) == REFUSED
        refusal = [m for m in messages if m[0] == REFUSED][-1][2]
        for word in expected_words + [f"t = {0.05!r} s"]:
            assert word in refusal, (word, refusal)
        # Nothing lost: the state is the last good point's. Outputs are held where
        # the inputs are invalid now; inputs valid at this instant (a rate that only
        # reaches the guard within the step, a step too long) show through, as
        # feedthrough demands.
        after = all_reals(joint)
        assert after["input_angle"] == before["input_angle"]
        if CardanJoint(**{**GOOD, **bad}).input_problem() is not None:
            assert [after[n] for n in table.OUTPUTS] == [before[n] for n in table.OUTPUTS]
        # The master fixes its inputs and retries: bit for bit as if nothing happened.
        for j in (joint, twin):
            j.set(**GOOD)
            for _ in range(5):
                j.step(0.01)
        assert joint.get_outputs() == twin.get_outputs()
    finally:
        joint.close()
        twin.close()


@pytest.mark.parametrize(
    "parameter, value, words",
    [
        ("max_bend_angle", 1.6, ["max_bend_angle = 1.6", "pi/2"]),
        ("max_bend_angle", 0.0, ["max_bend_angle = 0.0"]),
        ("crosspiece_inertia_2", -0.01, ["crosspiece_inertia_2 = -0.01", "range [0.0, "]),
        ("input_angle_start", 1e18, ["input_angle_start = 1e+18", "range"]),
        ("yoke_phase", math.nan, ["yoke_phase = nan", "finite"]),
        ("input_angle_start", math.inf, ["input_angle_start = inf"]),
    ],
)
def test_bad_parameters_refuse_every_step_and_say_why(
    model_description, unzipped_fmu, parameter, value, words
):
    messages = []
    joint = FmuInstance(
        model_description, unzipped_fmu, start_values={parameter: value}, messages=messages
    )
    try:
        assert joint.init_status == 3  # fmi2Error
        assert any(all(w in m[2] for w in words) for m in messages if m[0] == 3)  # ... and why
        for _ in range(3):
            assert joint.try_step(0.01) == REFUSED
        assert all(w in messages[-1][2] for w in words)
    finally:
        joint.close()  # terminate and free stay safe


def test_parameters_cannot_change_after_initialization(model_description, unzipped_fmu):
    messages = []
    joint = FmuInstance(model_description, unzipped_fmu, messages=messages)
    try:
        assert joint.try_set(crosspiece_inertia_1=5.0) == 3  # fmi2Error
        assert joint.get("crosspiece_inertia_1")["crosspiece_inertia_1"] == 0.026
        assert "parameter crosspiece_inertia_1 is fixed" in messages[-1][2]
        assert joint.try_step(0.01) == 0
    finally:
        joint.close()


def _extract_as_fmpy_does(fmu_path, folder):
    """resources/ and binaries/ only, as FMPy's simulate_fmu: no modelDescription.xml."""
    with zipfile.ZipFile(fmu_path) as archive:
        names = [n for n in archive.namelist() if n.startswith(("resources/", "binaries/"))]
        archive.extractall(folder, names)
    for library in (folder / "binaries").rglob("*.so"):
        library.chmod(0o755)
    return folder


def test_fixed_parameters_stay_fixed_after_restoring_a_state_from_before_initialization(
    model_description, fmu_path, tmp_path
):
    # The slave, restored to Initialization Mode, would take the value: only the
    # loader's guard refuses it, and it must not depend on modelDescription.xml.
    folder = _extract_as_fmpy_does(fmu_path, tmp_path)
    assert not (folder / "modelDescription.xml").exists()
    messages = []
    joint = FmuInstance(model_description, folder, messages=messages, exit_initialization=False)
    try:
        before = joint.get_state()
        assert joint.exit_initialization_mode() == 0
        joint.step(0.01)
        joint.set_state(before)
        assert joint.try_set(crosspiece_inertia_1=5.0) == 3  # fmi2Error
        assert joint.get("crosspiece_inertia_1")["crosspiece_inertia_1"] == 0.026
        assert "parameter crosspiece_inertia_1 is fixed" in messages[-1][2]
        joint.free_state(before)
    finally:
        joint.close()


def test_without_its_variable_record_the_fmu_refuses_to_instantiate(
    model_description, fmu_path, tmp_path
):
    folder = _extract_as_fmpy_does(fmu_path, tmp_path)
    (folder / "resources" / "variables.txt").unlink()
    messages = []
    with pytest.raises(Exception, match="(?i)instantiate"):
        FmuInstance(model_description, folder, messages=messages)
    assert any("variables.txt" in m[2] and "rebuild" in m[2] for m in messages)


def test_plain_simulate_fmu_shows_the_message_on_the_terminal(fmu_path):
    script = (
        "import numpy as np\nfrom fmpy import simulate_fmu\n"
        "u = np.array([(0.0, 0.5), (0.5, 0.5), (0.5, 1.5), (1.0, 1.5)],"
        " dtype=[('time', float), ('bend_angle', float)])\n"
        f"r = simulate_fmu({str(fmu_path)!r}, stop_time=1.0, output_interval=0.1, input=u)\n"
        "print('stopped at', r['time'][-1])\n"
    )
    run = subprocess.run(
        [sys.executable, "-c", script], capture_output=True, text=True, timeout=120
    )
    # A refused step is an error: FMPy raises (it stopped silently on fmi2Discard) ...
    assert run.returncode != 0 and "fmi2DoStep failed" in run.stderr
    # ... and the FMU says why: on stderr, as FMPy's default logger cannot be trusted
    # with logging off (its proxy may still point at a freed logger of an earlier run)
    assert "Error: t = 0.5 s: input bend_angle = 1.5 rad" in run.stderr
    assert "max_bend_angle" in run.stderr


def test_simulate_entry_point_raises_with_the_message(fmu_path):
    u = np.array(
        [(0.0, 0.5), (0.5, 0.5), (0.5, 1.5), (1.0, 1.5)],
        dtype=[("time", float), ("bend_angle", float)],
    )
    with pytest.raises(
        SimulationError, match=r"input bend_angle = 1.5 rad .* max_bend_angle"
    ) as error:
        simulate(fmu_path, stop_time=1.0, output_interval=0.1, inputs=u)
    assert error.value.result["time"][-1] == 0.5
