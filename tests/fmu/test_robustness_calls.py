"""Issue 4: hosts agree, bad calls are errors, invalid loads hold outputs,
builds refuse bad starts."""

import math

import numpy as np
import pytest
from conftest import run_build
from robustness_support import GOOD, all_reals

from cardan_joint.host.instance import FmuInstance, status_of
from cardan_joint.models.universal_joint import variables as table
from cardan_joint.models.universal_joint.model import CardanJoint


def test_libcosim_and_fmpy_agree_on_a_ten_second_run(fmu_path):
    from fmpy import simulate_fmu

    from cardan_joint.host.cosim import run_libcosim

    inputs = dict(
        input_speed=10.0,
        input_acceleration=0.0,
        bend_angle=0.5,
        bend_angle_rate=0.0,
        bend_angle_acceleration=0.0,
        load_torque=40.0,
    )
    names = list(table.OUTPUTS)
    cosim = run_libcosim(fmu_path, 10.0, 1e-3, inputs, names)
    fmpy = simulate_fmu(
        str(fmu_path), stop_time=10.0, output_interval=1e-3, start_values=inputs, output=names
    )
    assert len(cosim["time"]) == len(fmpy) == 10_001
    np.testing.assert_allclose(cosim["time"], fmpy["time"], rtol=0, atol=1e-12)
    for name in names:
        scale = np.max(np.abs(fmpy[name])) or 1.0
        assert np.max(np.abs(cosim[name] - fmpy[name])) <= 1e-9 * scale, name


def test_calls_for_other_types_and_bad_references_are_errors_not_fatal(
    model_description, unzipped_fmu
):
    messages = []
    joint = FmuInstance(model_description, unzipped_fmu, messages=messages)
    try:
        fmu = joint.fmu
        for call, arguments in (
            (fmu.getInteger, ([0],)),
            (fmu.getBoolean, ([0],)),
            (fmu.setInteger, ([0], [1])),
            (fmu.setBoolean, ([0], [True])),
            (fmu.getReal, ([9999],)),
        ):
            assert status_of(call, *arguments) == 3  # fmi2Error, never fmi2Fatal
        assert any("no Real variable has value reference 9999" in m[2] for m in messages)
        assert any("no Integer variables" in m[2] for m in messages)
        assert joint.try_step(0.01) == 0  # still alive and well
    finally:
        joint.close()


def test_a_garbage_serialized_state_is_refused_and_changes_nothing(model_description, unzipped_fmu):
    messages = []
    joint = FmuInstance(model_description, unzipped_fmu, messages=messages)
    try:
        joint.step(0.05)
        before = all_reals(joint)
        assert status_of(joint.deserialize_state, b"not a state at all") == 3  # fmi2Error
        assert "fmi2DeSerializeFMUstate refused the bytes" in messages[-1][2]
        assert all_reals(joint) == before
        joint.step(0.05)
    finally:
        joint.close()


def test_outputs_in_initialization_mode_see_the_parameters_at_once(model_description, unzipped_fmu):
    outputs = ("input_angle", "output_angle", "crosspiece_quaternion_0")
    with FmuInstance(
        model_description, unzipped_fmu, name="init", start_time=3.0, exit_initialization=False
    ) as joint:
        joint.set(input_angle_start=1.0, yoke_phase=0.5)
        in_init = joint.values(*outputs)
        joint.exit_initialization_mode()
        assert in_init == joint.values(*outputs)
        model = CardanJoint(input_angle_start=1.0, yoke_phase=0.5)
        assert in_init == list(model.outputs()[:2]) + [model.response().crosspiece_quaternion_0]


def test_invalid_load_holds_only_the_outputs_that_depend_on_it(model_description, unzipped_fmu):
    joint = FmuInstance(model_description, unzipped_fmu)
    try:
        joint.set(**GOOD)
        held = joint.get_outputs()
        joint.set(load_torque=math.nan, input_speed=20.0)
        now = joint.get_outputs()
        model = CardanJoint(**{**GOOD, "input_speed": 20.0})
        expected = dict(zip(table.OUTPUTS, model.outputs()))
        for name in table.OUTPUTS:
            if "load_torque" in table.BY_NAME[name].depends_on:
                assert now[name] == held[name], name  # held: depends on the NaN
            else:
                assert now[name] == expected[name], name  # follows the valid inputs
        assert now["output_speed"] != held["output_speed"]
    finally:
        joint.close()


def test_a_refused_step_leaves_the_clock_alone():
    from cardan_joint.fmi.slave import ModelSlave

    slave = type("Joint", (ModelSlave,), {"model_folder": "universal_joint"})(instance_name="clock")
    slave.setup_experiment(0.0)
    slave.exit_initialization_mode()
    assert slave.do_step(0.0, 0.5) is True
    saved = slave._get_fmu_state()
    slave.set_real([3], [1.5])  # bend_angle (the third variable) beyond the guard
    assert slave.do_step(123.0, 0.5) is False
    assert slave._get_fmu_state()["model"]["time"] == saved["model"]["time"] == 0.5


@pytest.mark.parametrize(
    "setting, words",
    [("bend_angle=2.0", "bend_angle = 2.0"), ("bend_angle=abc", "abc"), ("nonsense=1", "nonsense")],
)
def test_build_refuses_bad_start_values_with_a_message(tmp_path, setting, words):
    run = run_build(tmp_path, "--set", setting, timeout=120)
    assert run.returncode != 0
    assert words in run.stderr and "Traceback" not in run.stderr
    assert not list(tmp_path.glob("*.fmu"))
