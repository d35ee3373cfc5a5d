"""Issue 27 item 3 in the compliant drives: the rigid part's bearing loads and
life under the spring's torque, which follows the motion over a step. The damage
against mpmath's adaptive quadrature of the catalogue rate (`life_reference`),
the spring's torque at each instant rebuilt from the closed forms: the cardan
error and output speed from the full kernel, the lag as the polynomial it is.
The compliant propshaft's: tests/unit/test_propshaft_life.py."""

import json
import math

import pytest
from life_reference import damage

from cardan_joint.models.compliant_joint.model import CompliantJoint
from cardan_joint.models.compliant_propshaft.model import CompliantPropshaft
from cardan_joint.physics.life import life_rule
from cardan_joint.physics.response import joint_response

RULE = life_rule(1000.0, 1.5e6, 10.0 / 3.0, math.radians(3.0))


def _spring(model):
    """The spring's torque t s into the next step, from first principles."""
    rigid = model.rigid
    psi = rigid.input_angle + rigid.yoke_phase
    w1, a1 = rigid.input_speed, rigid.input_acceleration
    b, rb, ab = rigid.bend_angle, rigid.bend_angle_rate, rigid.bend_angle_acceleration
    wo, ao, lag = model.output_speed, model.output_acceleration, model._lag
    k, c = model.torsional_stiffness, model.torsional_damping

    def torque(t):
        r = joint_response(
            psi + w1 * t + 0.5 * a1 * t * t, b + rb * t + 0.5 * ab * t * t, w1 + a1 * t, a1,
            rb + ab * t, ab,
        )  # fmt: skip
        twist = r.cardan_error + lag + (w1 - wo) * t + 0.5 * (a1 - ao) * t * t
        return k * twist + c * (r.output_speed - (wo + ao * t))

    case = (psi, b, w1, a1, rb, ab, (rigid.crosspiece_inertia_1, rigid.crosspiece_inertia_2,
            rigid.crosspiece_inertia_3), torque)  # fmt: skip
    return case


@pytest.mark.parametrize(
    "values, h, steps",
    [
        # the output shaft slower, then overtaking: the spring's torque reverses
        (dict(input_speed=120.0, output_speed=118.0, output_acceleration=900.0,
              bend_angle=0.3, bend_angle_rate=0.5, torsional_stiffness=2e3), 0.01, 3),
        # the bend crossing 3 degrees, a stiff spring, a massless cross
        (dict(input_speed=-90.0, input_acceleration=400.0, output_speed=-91.0, bend_angle=0.07,
              bend_angle_rate=-1.5, crosspiece_inertia_1=0.0, crosspiece_inertia_2=0.0,
              crosspiece_inertia_3=0.0), 0.02, 3),
        # the spring's torque crossing zero steeply inside a step: the panels at
        # the zero need more nodes than the smooth part (3.9e-9 without them)
        (dict(input_speed=101.68328718593744, input_acceleration=2839.3601717315523,
              bend_angle=0.635242292606027, bend_angle_rate=-2.0733202573878473,
              torsional_stiffness=14072.1238381544, torsional_damping=13.205130303827417,
              twist_angle_start=-0.03570210020757628, output_speed=105.5116155225082,
              output_acceleration=3306.9049543979363), 1e-3, 1),
    ],
)  # fmt: skip
def test_the_compliant_joints_life_consumed_equals_an_adaptive_quadrature(values, h, steps):
    joint = CompliantJoint(**values)
    expected = 0.0
    for _ in range(steps):
        expected += damage(_spring(joint), h, RULE)
        assert joint.step(h) is None
        got = dict(zip(joint.table.OUTPUTS, joint.outputs()))["life_consumed"]
        assert abs(got - expected) <= 1e-9 * expected
    assert expected > 0.0


def test_the_compliant_joints_loads_and_rate_are_the_joints_under_the_spring():
    joint = CompliantJoint(input_speed=80.0, output_speed=78.0, bend_angle=0.25)
    joint.step(0.013)
    out = dict(zip(joint.table.OUTPUTS, joint.outputs()))
    rigid = joint.rigid
    rigid.load_torque = out["output_torque"]
    same = dict(zip(rigid.table.OUTPUTS, rigid.outputs()))
    for name in ("input_bearing_force", "output_bearing_force", "life_rate", "input_torque"):
        assert out[name] == same[name]


@pytest.mark.parametrize("make", [lambda: CompliantJoint(), lambda: CompliantPropshaft(3)])
def test_the_compliant_drives_save_their_life_mid_run(make):
    drive = make()
    drive.output_speed = drive.input_speed - 1.0
    for _ in range(5):
        drive.step(0.01)
    saved = json.loads(json.dumps(drive.state()))
    tail = [drive.outputs() for _ in range(3) if drive.step(0.01) is None]
    other = make()
    other.restore(saved)
    assert [other.outputs() for _ in range(3) if other.step(0.01) is None] == tail
    consumed = [v for n, v in zip(drive.table.OUTPUTS, tail[-1]) if n.endswith("life_consumed")]
    assert consumed and min(consumed) > 0.0
