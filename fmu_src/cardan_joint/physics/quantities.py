"""Single quantities of the joint, for scripts and sweeps.

Each picks one field of `joint_response` (where every equation lives), so
there is one formula text per quantity. Arguments: input-pin angle `psi` =
input angle + yoke phase, bend angle `beta`, and rates; scalars or arrays.
"""

from ._backend import Real, namespace
from .response import joint_response


def cardan_error(psi: Real, beta: Real) -> Real:
    """Delta = gamma2 - gamma1: bounded, continuous in psi."""
    return joint_response(psi, beta, 0.0).cardan_error


def output_angle(input_angle: Real, beta: Real, yoke_phase: Real = 0.0) -> Real:
    """gamma2 = gamma1 + Delta(gamma1 + phi, beta): closed form, no integration."""
    return input_angle + cardan_error(input_angle + yoke_phase, beta)


def speed_ratio(psi: Real, beta: Real) -> Real:
    """omega2 / omega1 at constant bend angle: cos b / D."""
    return joint_response(psi, beta, 0.0).speed_ratio


def output_speed(psi: Real, beta: Real, input_speed: Real, bend_angle_rate: Real = 0.0) -> Real:
    return joint_response(psi, beta, input_speed, 0.0, bend_angle_rate).output_speed


def max_cardan_error(beta: Real) -> Real:
    """Amplitude of the cardan error: atan((1 - cos b) / (2 sqrt(cos b)))."""
    xp = namespace(beta)
    cos_beta = xp.cos(beta)
    sin_beta = xp.sin(beta)
    return xp.atan(sin_beta * sin_beta / (1.0 + cos_beta) / (2.0 * xp.sqrt(cos_beta)))


def degree_of_unevenness(beta: Real) -> Real:
    """(omega2_max - omega2_min) / omega1 = tan b sin b."""
    xp = namespace(beta)
    return xp.tan(beta) * xp.sin(beta)


def roll_angle(psi: Real, beta: Real) -> Real:
    """Mityushov & Misyura's roll of the cross about the input pin: atan(tan b sin psi)."""
    xp = namespace(psi, beta)
    return xp.atan2(xp.sin(beta) * xp.sin(psi), xp.cos(beta))
