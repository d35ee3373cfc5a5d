"""The input angle kept as whole revolutions plus a compensated fraction."""

import math
from fractions import Fraction

from hypothesis import given, settings
from hypothesis import strategies as st

from cardan_joint.physics import advance, split_angle


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
