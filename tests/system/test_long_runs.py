"""Long runs (the slow layer): the joint stepped a million revolutions stays exact."""

import math
from fractions import Fraction

from cardan_joint.models.universal_joint.model import CardanJoint
from cardan_joint.physics import cardan_error


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
