"""Issue 14: every guard of the physics object has a test that fails without it
(tools/mutation.py disables each in turn). Each refusal is checked as data:
reason code, variable, value, limit, time; and the joint is left unchanged."""

import math

import pytest

from cardan_joint.framework import Reason
from cardan_joint.models.universal_joint import variables as table
from cardan_joint.models.universal_joint.model import CardanJoint
from cardan_joint.models.universal_joint.refusals import JointReason

GUARD = table.BY_NAME["max_bend_angle"].start
TINY = 1e-9  # a step too short for anything but the input itself to matter
RANGED_INPUTS = [n for n in table.INPUTS if n != "bend_angle"]
RANGED_PARAMETERS = [n for n in table.PARAMETERS if n != "max_bend_angle"]


def refused(joint, step_size, code, variable):
    """Step `joint`; check it refuses with `code` for `variable` and changes nothing."""
    before = joint.state()
    refusal = joint.step(step_size)
    assert refusal is not None, (code, variable)
    assert (refusal.code, refusal.variable) == (code, variable), refusal.message
    assert refusal.time == joint.time
    assert repr(joint.state()) == repr(before)  # repr: NaN equals itself
    return refusal


@pytest.mark.parametrize("sign", [1.0, -1.0])
@pytest.mark.parametrize("name", RANGED_INPUTS)
def test_each_input_beyond_its_range_is_refused(name, sign):
    high = table.BY_NAME[name].max
    joint = CardanJoint(**{name: sign * 2.0 * high})
    joint.time = 0.25
    refusal = refused(joint, TINY, Reason.OUT_OF_RANGE, name)
    assert (refusal.value, refusal.limit) == (sign * 2.0 * high, sign * high)
    assert refusal.details == {"low": -high, "high": high}
    assert joint.invalid_inputs() == {name}
    assert CardanJoint(**{name: sign * high}).step(TINY) is None  # the limit itself is fine


@pytest.mark.parametrize("value", [math.nan, math.inf, -math.inf])
@pytest.mark.parametrize("name", table.INPUTS)
def test_each_non_finite_input_is_refused(name, value):
    joint = CardanJoint(**{name: value})
    refusal = refused(joint, 1e-3, Reason.NOT_FINITE, name)
    assert repr(refusal.value) == repr(value)
    assert name in joint.invalid_inputs()


@pytest.mark.parametrize(
    "name, value",
    [
        (n, v)
        for n in RANGED_PARAMETERS
        for v in (2.0 * table.BY_NAME[n].max, -2.0 * table.BY_NAME[n].max)
    ],
)
def test_each_parameter_beyond_its_range_refuses_every_step(name, value):
    joint = CardanJoint(**{name: value})
    assert (joint.parameter_fault.code, joint.parameter_fault.variable) == (
        Reason.OUT_OF_RANGE,
        name,
    )
    joint.time = 3.0
    assert refused(joint, 1e-3, Reason.OUT_OF_RANGE, name).time == 3.0


@pytest.mark.parametrize("value", [math.nan, math.inf, -math.inf])
@pytest.mark.parametrize("name", table.PARAMETERS)
def test_each_non_finite_parameter_refuses_every_step(name, value):
    joint = CardanJoint(**{name: value})
    assert (joint.parameter_fault.code, joint.parameter_fault.variable) == (Reason.NOT_FINITE, name)
    refused(joint, 1e-3, Reason.NOT_FINITE, name)
    # The angle starts from zero, not from a value it cannot hold.
    assert joint.input_angle == 0.0 and all(math.isfinite(x) for x in joint.outputs()[:2])


@pytest.mark.parametrize("value", [0.0, -0.1, table.HALF_PI, 1.6])
def test_max_bend_angle_must_lie_strictly_inside_its_interval(value):
    joint = CardanJoint(max_bend_angle=value, bend_angle=0.0)
    refusal = refused(joint, 1e-3, JointReason.BEND_GUARD, "max_bend_angle")
    assert refusal.limit == (0.0 if value <= 0.0 else table.HALF_PI)


@pytest.mark.parametrize("step_size", [0.0, -1e-3, math.nan, math.inf, -math.inf])
def test_the_step_size_must_be_finite_and_positive(step_size):
    refusal = refused(CardanJoint(), step_size, Reason.STEP_SIZE, "step_size")
    assert repr(refusal.value) == repr(step_size)


def test_a_step_advancing_the_angle_beyond_float_precision_is_refused():
    refusal = refused(CardanJoint(input_speed=10.0), 1e15, Reason.ANGLE_OVERFLOW, "input_angle")
    assert refusal.value == 1e16 and refusal.limit == 1e15
    assert CardanJoint(input_speed=10.0).step(1e13) is None


def test_a_step_ending_beyond_the_speed_range_is_refused():
    joint = CardanJoint(input_speed=9e4, input_acceleration=1e8)
    refusal = refused(joint, 0.01, Reason.SPEED_OVERFLOW, "input_speed")
    assert refusal.value == 9e4 + 1e6 and refusal.details["step_size"] == 0.01


# --- the bend angle: now, at the step's end, and at its peak inside the step ---


def test_a_bend_angle_at_the_guard_is_refused_and_its_outputs_marked_invalid():
    joint = CardanJoint(bend_angle=-GUARD)
    assert refused(joint, 1e-3, JointReason.BEND_ANGLE, "bend_angle").limit == GUARD
    assert joint.invalid_inputs() == {"bend_angle"}


@pytest.mark.parametrize("sign", [1.0, -1.0])
def test_a_bend_angle_beyond_the_guard_is_refused_even_if_it_returns_within_the_step(sign):
    joint = CardanJoint(bend_angle=sign * 1.5, bend_angle_rate=-sign * 20.0)
    assert refused(joint, 0.01, JointReason.BEND_ANGLE, "bend_angle").value == sign * 1.5


@pytest.mark.parametrize("sign", [1.0, -1.0])
def test_a_bend_angle_reaching_the_guard_at_the_step_end_is_refused(sign):
    joint = CardanJoint(bend_angle=sign * 1.3, bend_angle_rate=sign * 20.0)
    refusal = refused(joint, 0.01, JointReason.BEND_AT_STEP_END, "bend_angle")
    assert refusal.value == sign * (1.3 + 0.2) and refusal.details["after"] == 0.01


# Both ends of the step inside the guard, the parabola over it in between.
PEAK = dict(bend_angle=1.38, bend_angle_rate=2.0, bend_angle_acceleration=-100.0)
PEAK_STEP = 0.04  # vertex at 0.02 s: 1.40 rad > 1.3963 rad; both ends 1.38 rad


def peaking(sign):
    return CardanJoint(**{name: sign * value for name, value in PEAK.items()})


@pytest.mark.parametrize("sign", [1.0, -1.0])
def test_a_bend_angle_peaking_over_the_guard_inside_the_step_is_refused(sign):
    joint = peaking(sign)
    assert joint.input_problem() is None  # fine at this instant
    assert joint.invalid_inputs() == set()
    for problem in (
        joint.input_problem(PEAK_STEP),  # fast path, then the explanation
        joint._explain_input_problem(PEAK_STEP),
    ):  # the slow path on its own
        assert problem.code == JointReason.BEND_PEAK_IN_STEP
        assert problem.value == pytest.approx(sign * 1.40, abs=1e-15)
        assert problem.details["after"] == pytest.approx(0.02, abs=1e-15)
    refused(joint, PEAK_STEP, JointReason.BEND_PEAK_IN_STEP, "bend_angle")
    # A shorter step stops before the peak, a longer one is refused at its end.
    assert peaking(sign).step(0.005) is None
    assert peaking(sign).step(0.05).code == JointReason.BEND_PEAK_IN_STEP


def test_a_peak_inside_the_step_below_the_guard_is_accepted():
    joint = CardanJoint(**{**PEAK, "bend_angle": 1.36})  # vertex at 1.38 rad
    assert joint.step(PEAK_STEP) is None
    assert joint.bend_angle == pytest.approx(1.36, abs=1e-15)


# --- state ---------------------------------------------------------------------


def test_restore_of_a_malformed_state_changes_nothing():
    joint = CardanJoint(input_speed=3.0)
    joint.step(0.1)
    before = joint.state()
    other = CardanJoint(input_speed=50.0, bend_angle=0.1)
    other.step(0.3)
    incomplete = other.state()
    del incomplete["turns"]
    with pytest.raises(KeyError):
        joint.restore(incomplete)
    assert joint.state() == before
    joint.restore(other.state())
    assert joint.state() == other.state()
