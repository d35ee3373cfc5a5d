"""The exact step of a driven rotor: J w' = torque - damping w with the torque
held over the step, solved in closed form (the motor's and the inertia load's
step, through `framework.stepped.RotorModel`)."""

import math


def _phi2(z: float) -> float:
    """(exp(z) - 1 - z) / z^2, without the cancellation of that formula near z = 0."""
    if abs(z) > 0.05:
        return (math.expm1(z) - z) / (z * z)
    # Taylor series 1/2 + z/6 + ... to z^8: truncation below 1e-19 for |z| <= 0.05.
    total, term = 0.0, 1.0
    for k in range(2, 11):
        term /= k
        total += term
        term *= z
    return total


def exact_rotor_step(speed: float, inertia: float, damping: float, torque: float, h: float):
    """(speed, angle increment) after `h` s of J w' = torque - damping w, the torque
    held: exact for any damping >= 0, zero included (then uniform acceleration).

    With a = (torque - damping w) / J and z = -damping h / J:
    w(h) = w + a h (e^z - 1)/z and the angle grows by w h + a h^2 (e^z - 1 - z)/z^2.
    """
    acceleration = (torque - damping * speed) / inertia
    z = -damping * h / inertia
    # expm1 keeps full precision when h is much shorter than the time constant.
    phi1 = math.expm1(z) / z if z != 0.0 else 1.0
    return speed + acceleration * h * phi1, h * (speed + acceleration * h * _phi2(z))
