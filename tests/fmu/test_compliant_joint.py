"""CompliantJoint: the rigid joint's kinematics (the independent geometric
reference) with a hand-written spring-damper law; refusals; the stiff limit; the FMU."""

import copy
import math

import numpy as np
import pytest
from reference.geometry import geometric_reference

from cardan_joint.framework import Reason, Refusal
from cardan_joint.host.instance import FmuInstance
from cardan_joint.models.compliant_joint.model import CompliantDrive, CompliantJoint
from cardan_joint.models.compliant_joint.refusals import CompliantReason
from cardan_joint.models.compliant_joint.variables import COMPLIANT_JOINT
from cardan_joint.models.inertia_load.model import InertiaLoad
from cardan_joint.models.universal_joint.model import CardanJoint
from cardan_joint.models.universal_joint.refusals import JointReason

INERTIA = (0.02, 0.03, 0.045)
START = dict(
    input_speed=12.0,
    input_acceleration=-3.0,
    output_speed=11.0,
    output_acceleration=2.0,
    bend_angle=0.4,
    bend_angle_rate=0.3,
    bend_angle_acceleration=-0.8,
    yoke_phase=0.7,
    input_angle_start=1.1,
    twist_angle_start=0.01,
    torsional_stiffness=3e3,
    torsional_damping=4.0,
    crosspiece_inertia_1=INERTIA[0],
    crosspiece_inertia_2=INERTIA[1],
    crosspiece_inertia_3=INERTIA[2],
)


def _reference(t, load_torque=0.0):
    """The rigid joint at time t by the geometric construction (mpmath)."""
    s = START
    return geometric_reference(
        t,
        lambda u: s["input_angle_start"] + u * (s["input_speed"] + s["input_acceleration"] * u / 2),
        lambda u: (
            s["bend_angle"] + u * (s["bend_angle_rate"] + s["bend_angle_acceleration"] * u / 2)
        ),
        yoke_phase=s["yoke_phase"],
        inertia=INERTIA,
        load_torque=load_torque,
    )


def test_spring_damper_on_the_geometric_kinematics_at_every_step():
    joint = CompliantJoint(**START)
    s, k, c = START, START["torsional_stiffness"], START["torsional_damping"]
    output_start = _reference(0.0)["output_angle"] - s["twist_angle_start"]
    names = COMPLIANT_JOINT.OUTPUTS
    for n in range(6):
        t = 0.05 * n
        if n:
            assert joint.step(0.05) is None
        rigid = _reference(t)
        # The hand-written law: the output shaft angle is the integral of its speed.
        output_speed = s["output_speed"] + s["output_acceleration"] * t
        output_angle = output_start + t * (s["output_speed"] + s["output_acceleration"] * t / 2)
        twist = rigid["output_angle"] - output_angle
        torque = k * twist + c * (rigid["output_speed"] - output_speed)
        loaded = _reference(t, torque)
        got = dict(zip(names, joint.outputs()))
        expected = {
            "input_angle": rigid["input_angle"],
            "output_angle": output_angle,
            "twist_angle": twist,
            "output_torque": torque,
            "kinematic_output_speed": rigid["output_speed"],
            "spring_energy": 0.5 * k * twist**2,
            **{n: loaded[n] for n in names if n in loaded and n not in ("output_angle",)},
        }
        for name, value in expected.items():
            scale = max(1.0, abs(value), abs(torque) if "torque" in name else 1.0)
            assert got[name] == pytest.approx(value, rel=0, abs=1e-9 * scale), (t, name)


def test_state_restores_exactly_and_refused_steps_change_nothing():
    joint = CompliantJoint(**START)
    joint.step(0.1)
    saved, outputs = joint.state(), joint.outputs()
    joint.output_speed = math.nan
    problem = joint.step(0.1)
    assert problem.code is Reason.NOT_FINITE and problem.variable == "output_speed"
    assert "input output_speed = nan rad/s" in problem.message
    assert joint.invalid_inputs() == {"output_speed"}
    joint.output_speed = 11.0 + 2.0 * 0.1
    assert joint.outputs() == outputs
    joint.step(0.3)
    joint.restore(saved)
    assert joint.outputs() == outputs and joint.time == pytest.approx(0.1)


@pytest.mark.parametrize(
    "change, variable, reason",
    [
        ({"torsional_stiffness": 0.0}, "torsional_stiffness", Reason.OUT_OF_RANGE),
        ({"torsional_damping": -1.0}, "torsional_damping", Reason.OUT_OF_RANGE),
        ({"max_bend_angle": 2.0}, "max_bend_angle", JointReason.BEND_GUARD),
        ({"output_acceleration": 1e9}, "output_acceleration", Reason.OUT_OF_RANGE),
        ({"bend_angle": 1.5, "bend_angle_rate": 0.0}, "bend_angle", JointReason.BEND_ANGLE),
    ],
)
def test_bad_parameters_and_inputs_are_refused_by_name(change, variable, reason):
    problem = CompliantJoint(**{**START, **change}).step(0.01)
    assert (problem.code, problem.variable) == (reason, variable)
    assert Refusal.from_message(problem.message) == problem


def test_a_start_with_an_unusable_bend_keeps_the_twist_usable_once_the_bend_is():
    # The start offset needs the kinematics, which a NaN bend angle does not have:
    # the output shaft then starts at the input angle (less the start twist).
    joint = CompliantJoint(bend_angle=math.nan, input_speed=1.0, output_speed=1.0)
    assert joint.step(0.1).code is Reason.NOT_FINITE
    joint.bend_angle = 0.3
    assert joint.step(0.1) is None
    assert all(math.isfinite(value) for value in joint.outputs())


def test_a_torque_beyond_the_rigid_load_range_is_no_refused_input():
    # The spring's torque reaches the rigid joint only inside outputs(): its
    # load_torque range does not apply to it.
    joint = CompliantJoint(torsional_stiffness=1e12, twist_angle_start=1e3)
    torque = dict(zip(COMPLIANT_JOINT.OUTPUTS, joint.outputs()))["output_torque"]
    assert torque > 1e9 and joint.step(0.01) is None


def test_a_copy_steps_as_the_original():
    joint = CompliantJoint(**START)
    twin = copy.deepcopy(joint)
    assert joint.step(0.1) is None and twin.step(0.1) is None
    assert twin.outputs() == joint.outputs()


def test_a_twist_beyond_the_angle_limit_is_refused():
    joint = CompliantJoint(input_speed=0.0, output_speed=1e5)
    problem = joint.step(1e11)
    assert (
        problem.code is CompliantReason.TWIST_OVERFLOW
        and "twist_angle by -1e+16 rad" in problem.message
    )
    assert joint.time == 0.0 and joint.output_angle == 0.0


def _driven(stiffness, stop=0.3):
    """A compliant joint at a constant input speed driving an inertia load, coupled
    at a step far below the torsional period, damping ratio 0.7; the input
    torque and load speed at `stop`."""
    inertia, drag, constant = 0.05, 0.02, 5.0
    damping = 2 * 0.7 * math.sqrt(stiffness * inertia)
    h = 2 * math.pi / math.sqrt(stiffness / inertia) / 50
    motion = dict(input_speed=20.0, bend_angle=0.35)
    joint = CompliantJoint(
        **motion, torsional_stiffness=stiffness, torsional_damping=damping, output_speed=20.0
    )
    load = InertiaLoad(inertia=inertia, drag=drag, constant_torque=constant, speed_start=20.0)
    for _ in range(round(stop / h)):
        outputs = dict(zip(COMPLIANT_JOINT.OUTPUTS, joint.outputs()))
        speed, acceleration, _ = load.outputs()
        load.drive_torque = outputs["output_torque"]
        joint.output_speed, joint.output_acceleration = speed, acceleration
        assert joint.step(h) is None and load.step(h) is None
    rigid = CardanJoint(**motion, input_angle_start=joint.input_angle)
    response = rigid.response()
    rigid.load_torque = inertia * response.output_acceleration + drag * load.speed + constant
    return (
        dict(zip(COMPLIANT_JOINT.OUTPUTS, joint.outputs()))["input_torque"]
        - dict(zip(rigid.table.OUTPUTS, rigid.outputs()))["input_torque"],
        load.speed - response.output_speed,
    )


def test_a_stiff_spring_approaches_the_rigid_joint():
    errors = np.abs([_driven(k) for k in (1e3, 1e4, 1e5)])
    # Torque and speed differences shrink with each tenfold stiffness.
    assert np.all(errors[1:] < 0.5 * errors[:-1]), errors
    assert errors[-1, 0] < 0.05 and errors[-1, 1] < 0.01, errors


def test_fmu_declares_feedthrough_and_steps_as_the_physics(compliant_joint_fmu_path):
    from fmpy import read_model_description
    from fmpy.validation import validate_fmu

    assert validate_fmu(str(compliant_joint_fmu_path)) == []
    description = read_model_description(str(compliant_joint_fmu_path))
    dependencies = {u.variable.name: {v.name for v in u.dependencies} for u in description.outputs}
    assert "output_speed" in dependencies["input_torque"]
    assert "output_speed" in dependencies["output_torque"] and dependencies["output_angle"] == set()
    model = CompliantJoint(**START)
    # The inputs too are set before initialization ends: the output shaft starts
    # behind the kinematic output for the bend angle at the start.
    with FmuInstance.open(str(compliant_joint_fmu_path), name="cj", start_values=START) as fmu:
        for k in range(3):
            fmu.time = k * 0.05
            fmu.step(0.05)
            model.step(0.05)
            fmu.set(output_speed=model.output_speed, input_speed=model.input_speed)
            fmu.set(bend_angle=model.bend_angle, bend_angle_rate=model.bend_angle_rate)
            assert tuple(fmu.get_outputs().values()) == pytest.approx(model.outputs(), rel=1e-15)


def test_declares_exactly_its_tables_inputs_and_parameters():
    declared = set(CompliantDrive.__annotations__) | set(CompliantJoint.__annotations__)
    assert declared == {*COMPLIANT_JOINT.INPUTS, *COMPLIANT_JOINT.PARAMETERS}
    joint = CompliantJoint()
    assert all(isinstance(getattr(joint, name), float) for name in declared)
