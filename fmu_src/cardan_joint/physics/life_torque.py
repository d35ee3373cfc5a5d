"""The joint's input torque alone, for the life integral's quadrature nodes.

The life rate needs only T1 = tau1 . z at each node, not the whole response
(`response.kernel`: cardan error, quaternion, energy, couples). These are
the kernel's own torque lines (response.py, same notation, same order of
operations), cut to what T1 needs; tests/unit/test_life_torque.py pins them
to the kernel over random cases. A massless cross needs only T_L cos b / D.
"""

import math

_sin, _cos, _sqrt = math.sin, math.cos, math.sqrt


def input_torque(psi, b, w1, a1, rb, ab, I1, I2, I3, load_torque):
    """T1 at input-pin angle `psi`, bend `b` with its rate and acceleration,
    input speed and acceleration, cross inertias and load (response.py)."""
    s = _sin(psi)
    c = _cos(psi)
    sb = _sin(b)
    cb = _cos(b)
    sbs = sb * s
    D = cb * cb + sbs * sbs
    if not (I1 or I2 or I3):
        return load_torque * cb / D
    sbc = sb * c
    sc = s * c
    rD = _sqrt(D)
    ccb = cb * c
    w1cb = w1 * cb
    w1sbs = w1 * sbs
    a1cb = a1 * cb
    w1rbsb = w1 * rb * sb
    w2 = (w1cb + rb * sb * sc) / D
    D_rate = 2.0 * sbc * (w1sbs - ccb * rb)
    a2 = (
        a1cb - w1rbsb + ab * sb * sc + rb * rb * cb * sc + w1rbsb * (c - s) * (c + s) - w2 * D_rate
    ) / D
    W1 = w2 * sbc + rb * s
    W2 = w1sbs / rD
    W3 = w1cb / rD
    half_log_rate = 0.5 * D_rate / D
    dW1 = a2 * sbc + w2 * (cb * rb * c - w1sbs) + ab * s + rb * c * w1
    dW2 = (a1 * sbs + w1cb * rb * s + w1 * w1 * sbc) / rD - W2 * half_log_rate
    dW3 = (a1cb - w1 * sb * rb) / rD - W3 * half_log_rate
    M1 = I1 * dW1 + (I3 - I2) * W2 * W3
    M2 = I2 * dW2 + (I1 - I3) * W3 * W1
    M3 = I3 * dW3 + (I2 - I1) * W1 * W2
    Dd = -(load_torque + M1 * sbc) / rD
    return (M2 * sbs + (M3 - Dd) * cb) / rD


def torque_over_step(psi, b, w1, a1, rb, ab, inertia, load_torque):
    """T1(t) for t s into a step whose inputs are polynomial over it (the
    speed at constant acceleration, the bend at constant acceleration, the
    load held): the function the life integral samples."""
    I1, I2, I3 = inertia

    def at(t):
        return input_torque(
            psi + t * (w1 + 0.5 * a1 * t),
            b + t * (rb + 0.5 * ab * t),
            w1 + a1 * t,
            a1,
            rb + ab * t,
            ab,
            I1,
            I2,
            I3,
            load_torque,
        )

    return at
