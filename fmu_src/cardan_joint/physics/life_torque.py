"""The joint's input torque alone, for the life integral's quadrature nodes.

The life rate needs only T1 = tau1 . z at each node, not the whole response:
the kernel's own parts that T1 needs (`response.pose_of`, `crosspiece_motion`,
`euler_moments`, `yoke_reactions`), so T1 here is the kernel's to the bit
from the same bend sine and cosine. A massless cross needs only T_L cos b / D.
"""

import math

from .response import crosspiece_motion, euler_moments, pose_of, yoke_reactions

# Up to this change of bend from the step's start, its sine and cosine follow
# from the start's by the addition formulas with the turn's own to its 7th and
# 8th power: the rest, below 3e-24, is far under an ulp of either.
_SMALL_TURN = 0.01
# Up to this one, to its 3rd and 4th power: the rest, below 1e-18 of the
# sine's and the cosine's change, is as far under an ulp. A bend turning at
# 0.1 rad/s or less over a 1 ms step stays below it; the terms left out took
# 1.8 % off the UniversalJoint's step at 1000 rad/s.
_TINY_TURN = 1e-4


def input_torque(psi, sb, cb, w1, a1, rb, ab, I1, I2, I3, load_torque):
    """T1 at input-pin angle `psi`, bend sine `sb` and cosine `cb`, the bend's
    rate and acceleration, input speed and acceleration, cross inertias and
    load (response.py)."""
    s, c, sb, cb, D, rD = pose_of(math, psi, sb, cb)[2:]
    if I1 == 0.0 and I2 == 0.0 and I3 == 0.0:
        return load_torque * cb / D
    # The cross's angular velocity and acceleration (the output speed aside).
    W1, W2, W3, dW1, dW2, dW3 = crosspiece_motion(s, c, sb, cb, D, rD, w1, a1, rb, ab)[2:]
    M1, M2, M3 = euler_moments(I1, I2, I3, W1, W2, W3, dW1, dW2, dW3)
    return yoke_reactions(M1, M2, M3, s, c, sb, cb, rD, load_torque)[2]


def turned(b, sb, cb, turn):
    """(sin, cos) of b + `turn`, sb and cb those of b: by the addition formulas
    for a small turn (a node of a step whose bend changes little costs no
    trigonometric call, and a tiny turn two terms fewer; none turns the bits
    of sb, cb), else directly."""
    if turn == 0.0:
        # A held bend: the formulas would add only zeros (4.7 % of the step at
        # the 10^6-revolution run's point; the test costs a moving bend's step
        # 0.5 % at 1000 rad/s: callgrind, the step alone).
        return sb, cb
    if abs(turn) > _SMALL_TURN:
        return math.sin(b + turn), math.cos(b + turn)
    t2 = turn * turn
    sine_rest, cosine_rest = 1.0, 1.0
    if abs(turn) > _TINY_TURN:
        sine_rest = 1.0 - t2 / 20.0 * (1.0 - t2 / 42.0)
        cosine_rest = 1.0 - t2 / 30.0 * (1.0 - t2 / 56.0)
    sine = turn * (1.0 - t2 / 6.0 * sine_rest)
    cosine_less_one = -0.5 * t2 * (1.0 - t2 / 12.0 * cosine_rest)
    return sb + (sb * cosine_less_one + cb * sine), cb + (cb * cosine_less_one - sb * sine)


def joint_torque(t, step):
    """(T1, input speed) t s into a step whose inputs are polynomial over it:
    `step` = (psi, b, w1, a1, rb, ab, I1, I2, I3, T_L, sin b, cos b) at its
    start, the speed and the bend at constant acceleration, the load held."""
    psi, b, w1, a1, rb, ab, I1, I2, I3, load, sb, cb = step
    speed = w1 + a1 * t
    sb, cb = turned(b, sb, cb, t * (rb + 0.5 * ab * t))
    torque = input_torque(
        psi + t * (w1 + 0.5 * a1 * t), sb, cb, speed, a1, rb + ab * t, ab, I1, I2, I3, load,
    )  # fmt: skip
    return torque, speed
