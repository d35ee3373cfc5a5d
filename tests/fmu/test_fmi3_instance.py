"""The FMI 3.0 FMU in one process: refusals, fixed parameters, state, reset, instances."""

import math

import numpy as np
import pytest
from test_fmi3 import _polynomial_laws

from cardan_joint.host.instance import FmuInstance
from cardan_joint.models.universal_joint import variables as table


@pytest.fixture
def joint3(fmi3_description, fmi3_unzipped):
    messages = []
    instance = FmuInstance(fmi3_description, fmi3_unzipped, name="joint3", messages=messages)
    instance.messages = messages
    yield instance
    instance.close()


def _state_bytes(joint):
    state = joint.get_state()
    try:
        return joint.serialize_state(state)
    finally:
        joint.free_state(state)


def test_a_bad_input_is_refused_with_its_message_and_nothing_is_lost(joint3):
    joint3.set(input_speed=30.0, bend_angle=0.3)
    joint3.step(0.05)
    outputs = joint3.get_outputs()
    before = _state_bytes(joint3)
    # Ends below the guard, crosses it mid-step (vertex of the bend parabola).
    joint3.set(bend_angle=1.3, bend_angle_rate=4.0, bend_angle_acceleration=-80.0)
    assert joint3.try_step(0.1) == 3  # a refused step: fmi3Error
    status, category, message = joint3.messages[-1]
    assert (status, category) == (3, "logStatusError")  # logged at the status returned
    for words in (
        "bend_angle",
        "max_bend_angle",
        "1.3962634015954636",
        "t = 0.05 s",
        "stays at t = 0.05 s",
    ):
        assert words in message
    joint3.set(bend_angle=0.3, bend_angle_rate=0.0, bend_angle_acceleration=0.0)
    assert _state_bytes(joint3) == before
    assert joint3.get_outputs() == outputs
    joint3.step(0.1)  # continues with corrected inputs
    assert joint3.get("time")["time"] == pytest.approx(0.15)


def test_parameters_are_fixed_after_initialization(joint3):
    from fmpy.fmi1 import FMICallException

    with pytest.raises(FMICallException) as refused:  # the worst status logged, as in FMI 2.0
        joint3.set(max_bend_angle=0.1)
    assert refused.value.status == 3
    assert joint3.messages[-1][:2] == (3, "logStatusError")
    assert "parameter max_bend_angle is fixed" in joint3.messages[-1][2]
    assert joint3.get("max_bend_angle")["max_bend_angle"] == table.BY_NAME["max_bend_angle"].start


def test_a_restored_state_from_before_initialization_does_not_unfix_parameters(
    fmi3_description, fmi3_unzipped
):
    from fmpy.fmi1 import FMICallException
    from fmpy.fmi3 import FMU3Slave

    fmu = FMU3Slave(
        guid=fmi3_description.guid,
        unzipDirectory=fmi3_unzipped,
        modelIdentifier=fmi3_description.coSimulation.modelIdentifier,
        instanceName="restored",
    )
    fmu.instantiate()
    before = fmu.getFMUState()
    fmu.enterInitializationMode()
    fmu.exitInitializationMode()
    fmu.setFMUState(before)  # the slave now believes it is not initialized
    reference = table.BY_NAME["max_bend_angle"]
    vr = next(
        v.valueReference for v in fmi3_description.modelVariables if v.name == "max_bend_angle"
    )
    with pytest.raises(FMICallException):
        fmu.setFloat64([vr], [0.1])
    assert fmu.getFloat64([vr]) == [reference.start]
    fmu.freeFMUState(before)
    fmu.freeInstance()


# The slave refuses what it may not do; the loader (native/fmi3_calls.c) refuses
# what does not fit modelDescription.xml before it reaches pythonfmu3.
@pytest.mark.parametrize(
    "call, message",
    [
        (
            lambda f, r: f.setFloat64([r["crosspiece_torque"]], [1.0, 2.0, 3.0]),
            "crosspiece_torque ignored",
        ),
        (lambda f, r: f.getFloat64([999], 4), "value reference 999 is not a variable"),
        (
            lambda f, r: f.getInt32([2], 1),
            "value reference 2 (input_speed, Float64) is of another type",
        ),
        (
            lambda f, r: f.setFloat64([2, 4], [1.0]),
            "nValues is 1 but the 2 value references hold 2",
        ),
        (lambda f, r: f.getFloat64([r["crosspiece_quaternion"]], 3), "hold 4 values"),
    ],
    ids=["output set", "unknown reference", "other type", "too few values", "array too short"],
)
def test_bad_calls_are_errors_in_the_log_never_fatal(joint3, call, message):
    from fmpy.fmi1 import FMICallException

    with pytest.raises(FMICallException) as refused:
        call(joint3.fmu, joint3.references)
    assert refused.value.status == 3
    assert message in joint3.messages[-1][2]
    assert {status for status, _, _ in joint3.messages} == {3}
    joint3.step(0.01)  # still alive


def test_state_round_trips_bit_for_bit(joint3, fmi3_description, fmi3_unzipped):
    inputs = _polynomial_laws(np.random.default_rng(7), 0.8)
    for k in range(50):
        joint3.set(**{n: float(v) for n, v in inputs(k * 0.01).items()})
        joint3.step(0.01)
    state = joint3.get_state()
    data = joint3.serialize_state(state)

    def run(joint):
        recorded = []
        for k in range(50, 80):
            joint.set(**{n: float(v) for n, v in inputs(k * 0.01).items()})
            joint.step(0.01)
            recorded.append(joint.get_outputs())
        return recorded

    first = run(joint3)
    joint3.set_state(state)
    joint3.time = 0.5
    assert run(joint3) == first
    joint3.free_state(state)
    fresh = FmuInstance(fmi3_description, fmi3_unzipped, name="fresh")
    try:
        restored = fresh.deserialize_state(data)
        fresh.set_state(restored)
        fresh.free_state(restored)
        fresh.time = 0.5
        assert run(fresh) == first
    finally:
        fresh.close()


def test_reset_returns_to_the_start_values(joint3):
    start = joint3.get_outputs()
    joint3.set(input_speed=100.0)
    joint3.step(0.3)
    joint3.fmu.reset()
    joint3.fmu.enterInitializationMode()
    joint3.fmu.exitInitializationMode()
    assert joint3.get_outputs() == start


def test_many_instances_in_one_process_are_independent(fmi3_description, fmi3_unzipped):
    joints = [
        FmuInstance(
            fmi3_description, fmi3_unzipped, name=f"j{i}", start_values={"input_speed": 1.0 + i}
        )
        for i in range(40)
    ]
    try:
        for joint in joints:
            joint.step(0.1)
        angles = [joint.get("input_angle")["input_angle"] for joint in joints]
        assert angles == [0.1 * (1.0 + i) for i in range(40)]
    finally:
        for joint in joints:
            joint.close()


def test_an_internal_fault_in_a_step_is_an_error_status_not_an_exception(monkeypatch):
    from pythonfmu3.enums import Fmi3Status

    from cardan_joint.fmi.slave3 import TIME_REFERENCE, ModelSlave3

    class Joint(ModelSlave3):
        model_folder = "universal_joint"

    slave = Joint(instance_name="faulty")
    slave.enter_initialization_mode()
    slave.exit_initialization_mode()
    monkeypatch.setattr(slave._model, "run", lambda time, step_size, inputs: 1 / 0)
    assert slave.do_step(0.0, 0.1).status == Fmi3Status.error
    assert "internal error in do_step: ZeroDivisionError" in slave.log_queue[-1].msg
    assert slave.get_float64([TIME_REFERENCE])[0] == 0.0  # the clock stays at the step's start


def test_the_model_description_carries_the_builds_start_values():
    from cardan_joint.fmi.slave3 import ModelSlave3

    class Bent(ModelSlave3):
        model_folder = "universal_joint"
        start_overrides = {"bend_angle": 0.2, "max_bend_angle": math.nextafter(1.2, 2.0)}

    variables = {v.get("name"): v for v in Bent(instance_name="bent").to_xml().iter("Float64")}
    assert variables["bend_angle"].get("start") == "0.2"
    assert float(variables["max_bend_angle"].get("start")) == math.nextafter(1.2, 2.0)


def test_an_invalid_input_holds_the_same_outputs_as_fmi2(
    model_description, unzipped_fmu, fmi3_description, fmi3_unzipped
):
    messages = []
    joints = [
        FmuInstance(model_description, unzipped_fmu, name="held2"),
        FmuInstance(fmi3_description, fmi3_unzipped, name="held3", messages=messages),
    ]
    try:
        for joint in joints:
            joint.set(input_speed=40.0, load_torque=100.0)
            joint.step(0.1)
        valid = [joint.get_flat_outputs() for joint in joints][1]  # what each holds
        for joint in joints:
            joint.set(input_speed=20.0, load_torque=math.nan)
        fmi2, fmi3 = (joint.get_flat_outputs() for joint in joints)
        assert fmi3 == fmi2
        assert fmi3["input_torque"] == valid["input_torque"]  # held
        assert fmi3["output_speed"] != valid["output_speed"]  # follows the speed
        assert messages[-1][:2] == (1, "logStatusWarning") and "load_torque" in messages[-1][2]
    finally:
        for joint in joints:
            joint.close()
