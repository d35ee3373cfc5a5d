"""The joint's input torque alone, for the life integral's quadrature nodes.

The life rate needs only T1 = tau1 . z at each node, not the whole response:
the kernel's own parts that T1 needs (`response.pose`, `crosspiece_motion`,
`euler_moments`, `yoke_reactions`), so T1 here is the kernel's to the bit. A
massless cross needs only T_L cos b / D.
"""

import math

from .response import crosspiece_motion, euler_moments, pose, yoke_reactions


def input_torque(psi, b, w1, a1, rb, ab, I1, I2, I3, load_torque):
    """T1 at input-pin angle `psi`, bend `b` with its rate and acceleration,
    input speed and acceleration, cross inertias and load (response.py)."""
    s, c, sb, cb, D, rD = pose(math, psi, b)[2:]
    if I1 == 0.0 and I2 == 0.0 and I3 == 0.0:
        return load_torque * cb / D
    # The cross's angular velocity and acceleration (the output speed aside).
    W1, W2, W3, dW1, dW2, dW3 = crosspiece_motion(s, c, sb, cb, D, rD, w1, a1, rb, ab)[2:]
    M1, M2, M3 = euler_moments(I1, I2, I3, W1, W2, W3, dW1, dW2, dW3)
    return yoke_reactions(M1, M2, M3, s, c, sb, cb, rD, load_torque)[2]


def joint_torque(t, step):
    """(T1, input speed) t s into a step whose inputs are polynomial over it:
    `step` = (psi, b, w1, a1, rb, ab, I1, I2, I3, T_L) at its start, the speed
    and the bend at constant acceleration, the load held."""
    psi, b, w1, a1, rb, ab, I1, I2, I3, load = step
    speed = w1 + a1 * t
    torque = input_torque(
        psi + t * (w1 + 0.5 * a1 * t), b + t * (rb + 0.5 * ab * t), speed, a1, rb + ab * t, ab,
        I1, I2, I3, load,
    )  # fmt: skip
    return torque, speed
