"""The input angle kept as whole revolutions plus a compensated fraction."""

import math
from fractions import Fraction

from hypothesis import given, settings
from hypothesis import strategies as st

from cardan_joint.models.universal_joint.model import CardanJoint
from cardan_joint.physics import advance, cardan_error, split_angle


def exact(angle):
    """The stored angle as an exact rational, with 2 pi to 40 digits."""
    two_pi = Fraction("6.283185307179586476925286766559005768394")
    return angle.turns * two_pi + Fraction(angle.fraction) + Fraction(angle.fraction_error)


@settings(max_examples=300, deadline=None)
@given(st.floats(-1e9, 1e9))
def test_split_angle_round_trips(angle):
    a = split_angle(angle)
    assert 0.0 <= a.fraction <= 2 * math.pi
    # Absolute precision at the scale of one turn: a tiny negative angle wraps to
    # just below 2 pi and keeps ~1e-16 rad, not its own 1e-180.
    assert abs(float(a) - angle) <= math.ulp(max(abs(angle), 2 * math.pi))


@settings(max_examples=100, deadline=None)
@given(st.floats(0.0, 5.0), st.floats(1e-4, 0.5))
def test_advance_adds_without_drift(start, increment):
    a = split_angle(start)
    for _ in range(2000):
        a = advance(a, increment)
    expected = Fraction(start) + 2000 * Fraction(increment)
    assert abs(exact(a) - expected) < Fraction(1, 10**13)


def test_a_million_revolutions_at_constant_speed_stay_exact():
    # 1e6 revolutions of 2 pi * 0.98 rad per step at 0.5 s: the stepped joint's
    # input and output angle against exact rational arithmetic.
    speed = 2 * math.pi * 1.96  # rad/s
    step = 0.5
    steps = 1_020_409  # a little over 1e6 revolutions
    # Without life: the angle is the subject here, and a million steps of a turn
    # each would integrate a million damage increments for nothing.
    joint = CardanJoint(False, input_speed=speed, bend_angle=0.5, yoke_phase=0.3)
    for _ in range(steps):
        assert joint.step(step) is None
    two_pi = Fraction("6.283185307179586476925286766559005768394")
    exact_input = steps * Fraction(speed) * Fraction(step)
    assert exact_input / two_pi > 1e6
    assert abs(float(exact_input - Fraction(joint.input_angle))) < 1e-8
    exact_input_float = float(exact_input)
    turns = math.floor(exact_input / two_pi)
    fraction = float(exact_input - turns * two_pi)
    expected_output = exact_input + Fraction(cardan_error(fraction + 0.3, 0.5))
    outputs = joint.outputs()
    assert abs(float(Fraction(outputs[1]) - expected_output)) < 1e-8
    assert abs(outputs[0] - exact_input_float) <= math.ulp(exact_input_float)
