"""Issue 14: the slave's guards, each with a test that fails without it
(tools/mutation.py disables each in turn): the refused step and held outputs as
the FMU logs them, illegal calls, and state checks; and the bend angle peaking
inside a step, through the FMU."""

import json
import math

import pytest
from pythonfmu.enums import Fmi2Status

from cardan_joint.fmi.slave import ModelSlave
from cardan_joint.framework import Refusal
from cardan_joint.host.instance import FmuInstance
from cardan_joint.models.universal_joint import variables as table
from cardan_joint.models.universal_joint.model import CardanJoint
from cardan_joint.models.universal_joint.refusals import JointReason


class Joint(ModelSlave):
    model_folder = "universal_joint"


# Value reference r is the r-th variable (1-based); POSITION indexes get_real(ALL).
POSITION = {name: k for k, name in enumerate(v.name for v in table.VARIABLES)}
REFERENCE = {name: k + 1 for name, k in POSITION.items()}
ALL = list(REFERENCE.values())
PEAK = dict(bend_angle=1.38, bend_angle_rate=2.0, bend_angle_acceleration=-100.0)
PEAK_STEP = 0.04  # both ends at 1.38 rad, the vertex at 1.40 rad > 80 deg


def initialized(**start):
    slave = Joint(instance_name="guarded")
    slave.setup_experiment(0.0)
    slave.set_real([REFERENCE[n] for n in start], list(start.values()))
    slave.exit_initialization_mode()
    return slave


def last(slave, status):
    return [m.msg for m in slave.log_queue if m.status == status][-1]


def test_the_slave_refuses_a_step_peaking_inside_it_and_names_the_peak():
    slave = initialized()
    assert slave.do_step(0.0, 0.1) is True
    before = slave.get_real(ALL)
    slave.set_real([REFERENCE[n] for n in PEAK], list(PEAK.values()))
    assert slave.do_step(0.1, PEAK_STEP) is False
    refusal = Refusal.from_message(last(slave, Fmi2Status.error))
    assert (refusal.code, refusal.time) == (JointReason.BEND_PEAK_IN_STEP, 0.1)
    assert (
        slave._model.time == 0.1
        and slave.get_real([REFERENCE["input_angle"]])
        == before[POSITION["input_angle"] : POSITION["input_angle"] + 1]
    )


def test_outputs_with_invalid_inputs_are_held_and_the_warning_names_the_input():
    slave = initialized()
    held = slave.get_real(ALL)
    slave.set_real([REFERENCE["bend_angle"]], [1.5])
    assert slave.get_real(ALL)[POSITION["output_speed"]] == held[POSITION["output_speed"]]
    refusal = Refusal.from_message(last(slave, Fmi2Status.warning))
    assert (refusal.code, refusal.variable, refusal.value) == (
        JointReason.BEND_ANGLE,
        "bend_angle",
        1.5,
    )


def test_bad_parameters_are_an_error_at_initialization():
    slave = initialized(max_bend_angle=1.6)
    refusal = Refusal.from_message(last(slave, Fmi2Status.error))
    assert (refusal.code, refusal.value) == (JointReason.BEND_GUARD, 1.6)
    assert slave.do_step(0.0, 0.1) is False
    assert Refusal.from_message(last(slave, Fmi2Status.error)).code == JointReason.BEND_GUARD


@pytest.mark.parametrize(
    "reference, words",
    [
        (REFERENCE["input_angle"], "input_angle ignored: only inputs and parameters can be set"),
        *[
            (unknown, f"no Real variable has value reference {unknown}")
            for unknown in (0, len(table.VARIABLES) + 1, -1)
        ],
    ],
)
def test_setting_an_output_or_an_unknown_reference_is_an_error_and_changes_nothing(
    reference, words
):
    slave = initialized()
    before = slave.get_real(ALL)
    slave.set_real([reference], [123.0])
    assert words in last(slave, Fmi2Status.error)
    assert slave.get_real(ALL) == before


def test_reading_an_unknown_reference_is_an_error():
    slave = initialized()
    assert math.isnan(slave.get_real([9999])[0])
    assert "no Real variable has value reference 9999" in last(slave, Fmi2Status.error)


def test_a_parameter_set_after_initialization_is_ignored():
    slave = initialized()
    slave.set_real([REFERENCE["crosspiece_inertia_1"]], [5.0])
    assert "crosspiece_inertia_1 = 5.0 ignored" in last(slave, Fmi2Status.error)
    assert slave.get_real([REFERENCE["crosspiece_inertia_1"]]) == [0.026]


@pytest.mark.parametrize(
    "call, answer",
    [
        ("get_integer", [0]),
        ("get_boolean", [False]),
        ("get_string", [""]),
        ("set_integer", None),
        ("set_boolean", None),
        ("set_string", None),
    ],
)
def test_calls_for_other_variable_types_are_errors_not_exceptions(call, answer):
    slave = initialized()
    method = getattr(slave, call)
    result = method([0]) if call.startswith("get") else method([0], [1])
    assert result == answer
    assert "the FMU has no" in last(slave, Fmi2Status.error)


def restored(slave, state, words):
    """Set `state`; check it is refused with `words` and the slave keeps its state,
    its outputs' cache included (a read after it is not evaluated again)."""
    before, saved = slave.get_real(ALL), slave._get_fmu_state()
    cached = slave._outputs
    assert cached is not None
    assert slave._set_fmu_state(state) is True
    assert words in last(slave, Fmi2Status.error)
    assert slave._outputs is cached
    assert slave.get_real(ALL) == before and slave._get_fmu_state() == saved


@pytest.mark.parametrize(
    "data, words",
    [
        (b"not json", "got no valid state"),
        (b"[1, 2]", "not a serialized FMU state of this project"),
    ],
)
def test_a_serialized_state_that_is_no_state_is_refused(data, words):
    slave = initialized()
    before = slave._get_fmu_state()
    assert slave._fmu_state_from_bytes(data) is None
    assert "fmi2DeSerializeFMUstate refused the bytes" in last(slave, Fmi2Status.error)
    assert slave._get_fmu_state() == before
    restored(slave, json.loads(data) if data.startswith(b"[") else {"invalid_state": words}, words)


def test_a_state_without_its_start_time_changes_nothing():
    """The whole state is checked before any of it is applied."""
    slave, other = initialized(), initialized(input_speed=77.0)
    other.do_step(0.0, 0.3)
    state = other._get_fmu_state()
    del state["start_time"]
    restored(slave, state, "start_time")


def test_a_state_of_another_fmu_version_is_refused():
    slave, other = initialized(), initialized(input_speed=77.0)
    other.do_step(0.0, 0.3)
    state = json.loads(ModelSlave._fmu_state_to_bytes(other._get_fmu_state()))
    state["outputs_held"] = state["outputs_held"][:-1]
    restored(slave, state, "another version")


def test_a_state_saved_by_the_previous_release_is_refused_by_name():
    """1.0 kept the model's values under "joint", in another format."""
    slave, other = initialized(), initialized(input_speed=77.0)
    state = json.loads(ModelSlave._fmu_state_to_bytes(other._get_fmu_state()))
    state["joint"] = state.pop("model")
    restored(slave, state, "another version")


def test_a_state_missing_a_joint_value_is_refused():
    slave, other = initialized(), initialized(input_speed=77.0)
    other.do_step(0.0, 0.3)
    state = other._get_fmu_state()
    del state["model"]["fraction_error"]
    restored(slave, state, "KeyError")


@pytest.mark.parametrize("sign", [1.0, -1.0])
def test_the_fmu_refuses_a_bend_peak_inside_the_step(model_description, unzipped_fmu, sign):
    messages = []
    joint = FmuInstance(model_description, unzipped_fmu, name="peak", messages=messages)
    twin = CardanJoint()
    try:
        joint.step(0.1)
        twin.step(0.1)
        before = joint.get_outputs()
        peak = {name: sign * value for name, value in PEAK.items()}
        joint.set(**peak)
        assert joint.try_step(PEAK_STEP) == 3
        refusal = Refusal.from_message(messages[-1][2])
        for name, value in peak.items():
            setattr(twin, name, value)
        assert refusal == twin.step(PEAK_STEP)  # the same refusal, as data
        assert refusal.code == JointReason.BEND_PEAK_IN_STEP and refusal.time == 0.1
        assert joint.get("input_angle") == {"input_angle": before["input_angle"]}
        joint.set(bend_angle_acceleration=0.0, bend_angle_rate=0.0)
        assert joint.try_step(PEAK_STEP) == 0  # fixed: the same step goes
    finally:
        joint.close()
