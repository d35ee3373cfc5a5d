"""Issue 14: refusals as data. The FMU's copy of the package speaks to its host
only through log text, so every reason's message must parse back exactly."""

import math

import numpy as np
import pytest

from cardan_joint.framework import Reason, Refusal
from cardan_joint.framework.refusal import reasons
from cardan_joint.host.simulate import RefusalError, SimulationError, simulate
from cardan_joint.models.compliant_joint.model import CompliantJoint
from cardan_joint.models.compliant_joint.refusals import CompliantReason
from cardan_joint.models.inertia_load.model import InertiaLoad
from cardan_joint.models.inertia_load.refusals import InertiaLoadReason
from cardan_joint.models.motor.model import Motor
from cardan_joint.models.motor.refusals import MotorReason
from cardan_joint.models.propshaft import Propshaft
from cardan_joint.models.propshaft.refusals import PropshaftReason
from cardan_joint.models.universal_joint import variables as table
from cardan_joint.models.universal_joint.model import CardanJoint
from cardan_joint.models.universal_joint.refusals import JointReason

GUARD = table.BY_NAME["max_bend_angle"].start
# One way to meet each reason: (start values, step size).
CAUSES = {
    Reason.NOT_FINITE: [
        (dict(input_speed=math.nan), 0.1),
        (dict(load_torque=-math.inf), 0.1),
        (dict(yoke_phase=math.inf), 0.1),
        (dict(bend_angle=math.nan), 0.1),
    ],
    Reason.OUT_OF_RANGE: [
        (dict(input_acceleration=-1.5e8), 0.1),
        (dict(crosspiece_inertia_3=-1e-300), 0.1),
    ],
    JointReason.BEND_ANGLE: [(dict(bend_angle=-1.5), 0.1)],
    JointReason.BEND_AT_STEP_END: [(dict(bend_angle=1.3, bend_angle_rate=1.0 / 3.0), 0.5)],
    JointReason.BEND_PEAK_IN_STEP: [
        (dict(bend_angle=-1.38, bend_angle_rate=-2.0, bend_angle_acceleration=100.0), 0.04)
    ],
    JointReason.BEND_GUARD: [(dict(max_bend_angle=1.6), 0.1), (dict(max_bend_angle=-0.0), 0.1)],
    Reason.STEP_SIZE: [({}, -math.inf), ({}, math.nan), ({}, -5e-324)],
    Reason.ANGLE_OVERFLOW: [(dict(input_speed=-0.1), 1e17)],
    Reason.SPEED_OVERFLOW: [(dict(input_speed=0.1 + 0.2, input_acceleration=1e8), 0.7)],
    # The propshaft's own parameters.
    PropshaftReason.SHAFT_ANGLE: [(dict(shaft_1_top_angle=-math.pi / 2), 0.1)],
    PropshaftReason.WORKING_ANGLE_GUARD: [(dict(max_working_angle=2.0), 0.1)],
    PropshaftReason.WORKING_ANGLE: [(dict(shaft_1_side_angle=0.6, max_working_angle=0.5), 0.1)],
    PropshaftReason.TUBE_BORE: [(dict(shaft_1_inner_diameter=0.2), 0.1)],
    # The motor's.
    MotorReason.ROTOR_SPEED: [
        (dict(load_torque=9e8, stall_torque=60.0, no_load_speed=100.0, rotor_inertia=0.3), 0.1)
    ],
    # The inertia load's.
    InertiaLoadReason.LOAD_SPEED: [(dict(drive_torque=9e8, inertia=0.3, drag=0.0), 0.1)],
    # The compliant drive's.
    CompliantReason.TWIST_OVERFLOW: [(dict(input_speed=0.0, output_speed=-1e5), 1e11)],
}
PROPSHAFT_REASONS = {
    PropshaftReason.SHAFT_ANGLE,
    PropshaftReason.WORKING_ANGLE_GUARD,
    PropshaftReason.WORKING_ANGLE,
    PropshaftReason.TUBE_BORE,
}
MOTOR_REASONS = {MotorReason.ROTOR_SPEED}


def _model(reason, start):
    if reason in MOTOR_REASONS:
        return Motor(**start)
    if reason is InertiaLoadReason.LOAD_SPEED:
        return InertiaLoad(**start)
    if reason is CompliantReason.TWIST_OVERFLOW:
        return CompliantJoint(**start)
    return Propshaft(**start) if reason in PROPSHAFT_REASONS else CardanJoint(**start)


def test_every_reason_has_a_cause():
    assert set(CAUSES) == set(reasons())


@pytest.mark.parametrize("time", [0.0, 0.1 + 0.2, 1e-300, 12345.678901234567])
@pytest.mark.parametrize("reason", list(CAUSES))
def test_each_refusal_reads_back_exactly_from_its_message(reason, time):
    for start, step_size in CAUSES[reason]:
        joint = _model(reason, start)
        joint.time = time
        refusal = joint.step(step_size)
        assert refusal.code == reason
        assert refusal.variable and refusal.unit and not math.isnan(refusal.limit)
        # As the FMU logs it: the refusal inside a longer line.
        line = f"{refusal.message}; step of {step_size!r} s refused, the joint stays at t = 1.0 s"
        back = Refusal.from_message(line)
        assert back == refusal and back.message == refusal.message
        assert [repr(x) for x in (back.value, back.limit, back.time)] == [
            repr(x) for x in (refusal.value, refusal.limit, refusal.time)
        ]
        assert back.details == refusal.details or math.isnan(refusal.value)


def test_a_model_declares_its_own_reasons(monkeypatch):
    from enum import Enum

    from cardan_joint.framework import refusal as registry
    from cardan_joint.framework.refusal import register_reasons

    for name in ("_REASONS", "_TEMPLATES", "_PATTERNS", "_IMPLIED"):
        monkeypatch.setattr(registry, name, dict(getattr(registry, name)))

    class Untemplated(str, Enum):
        JAM = "jam"

    with pytest.raises(ValueError, match="Untemplated.JAM has no message template"):
        register_reasons(Untemplated, {})

    class Shared(str, Enum):
        RANGE = "out_of_range"

    with pytest.raises(ValueError, match="'out_of_range' is already declared by the shared"):
        register_reasons(Shared, {Shared.RANGE: "x {value} {limit}"})
    # A model's codes are its own: a second enumeration of the motor's folder may
    # not declare its code again ...
    again = Enum("Again", {"ROTOR": "rotor_speed"}, type=str, module=MotorReason.__module__)
    with pytest.raises(ValueError, match="'rotor_speed' is already declared by .*models.motor"):
        register_reasons(again, {again.ROTOR: "x {value} {limit}"})
    # ... another folder may (a copied model), with its own template.
    copied = Enum(
        "CopiedReason",
        {"ROTOR_SPEED": "rotor_speed"},
        type=str,
        module="cardan_joint.models.copied_motor.refusals",
    )
    register_reasons(copied, {copied.ROTOR_SPEED: "the copy's rotor: {value} rad/s > {limit}"})
    refusal = Refusal(copied.ROTOR_SPEED, "speed", 2.0, 1.0, 0.5, "rad/s")
    assert refusal.message == "t = 0.5 s: the copy's rotor: 2.0 rad/s > 1.0"
    assert Refusal.from_message(refusal.message).code is copied.ROTOR_SPEED
    motor = Refusal(
        MotorReason.ROTOR_SPEED,
        "speed",
        2.0,
        1.0,
        0.5,
        "rad/s",
        {"load_torque": 3.0, "step_size": 0.1},
    )
    assert "drives the rotor speed" in motor.message
    assert Refusal.from_message(motor.message).code is MotorReason.ROTOR_SPEED
    # The motor's reason lives in its folder, not in the shared enumeration.
    assert MotorReason.ROTOR_SPEED in reasons() and "ROTOR_SPEED" not in Reason.__members__


def test_the_message_names_variable_value_limit_and_time():
    refusal = CardanJoint(bend_angle=1.5).step(0.1)
    assert refusal.message == (
        "t = 0.0 s: input bend_angle = 1.5 rad (85.9437 deg) is not below "
        "the limit max_bend_angle = 1.3962634015954636 rad (80 deg)"
    )
    assert refusal.at(2.5).time == 2.5 and refusal.at(2.5).message.startswith("t = 2.5 s: ")


def test_text_without_a_refusal_is_not_parsed():
    with pytest.raises(ValueError):
        Refusal.from_message("internal error in do_step: ZeroDivisionError: division by zero")


def test_simulate_raises_the_refusal_with_its_fields(fmu_path):
    u = np.array(
        [(0.0, 0.5), (0.5, 0.5), (0.5, 1.5), (1.0, 1.5)],
        dtype=[("time", float), ("bend_angle", float)],
    )
    with pytest.raises(RefusalError) as error:
        simulate(fmu_path, stop_time=1.0, output_interval=0.1, inputs=u, output=["bend_angle"])
    e = error.value
    assert isinstance(e, SimulationError) and e.result["time"][-1] == 0.5 and e.messages
    # One row per time, the last one the good point (not the refused inputs).
    assert np.all(np.diff(e.result["time"]) > 0) and e.result["bend_angle"][-1] == 0.5
    assert "step of 0.1 s refused, the joint stays at t = 0.5 s" in str(e)
    assert (e.variable, e.value, e.limit, e.time, e.code, e.unit) == (
        "bend_angle",
        1.5,
        GUARD,
        0.5,
        JointReason.BEND_ANGLE,
        "rad",
    )
    assert e.refusal.message in str(e)
