"""Trunnion bearing loads and catalogue life of a Cardan joint (docs/life.md).

Bearing force: yoke k acts on the cross with a torque tau_k normal to its pin,
carried by its two trunnions at radius r, so each of those needle bearings
carries |tau_k| / (2 r); |tau_1|^2 = T1^2 + C1^2 (its shaft-axis part and the
secondary couple), |tau_2|^2 = T_L^2 + C2^2.

Life: the joint makers' rule for needle-bearing B10 life,
L_h = K / (A n) (T_r / |T|)^p hours, A = max(|b|, A_min) in degrees, n = |w1|
in rpm, T = T1; damage is Miner's sum of dt / (3600 L_h). Over a step whose
inputs are polynomial (speed and bend at constant acceleration, load held)
the rate is known in closed form at every instant: the common step (no kink,
one torque sign) is one Gauss-Legendre panel here, any other goes to
`life_integral.life_increment` (panels between the kinks).
Pure Python, standard library only.
"""

import math
from typing import NamedTuple

from .life_integral import FLAT_REACH, life_increment
from .life_torque import input_torque, torque_over_step
from .quadrature import gauss_unit_rule
from .response import JointResponse, kernel

_RAD_TO_DEG = 180.0 / math.pi
_RAD_S_TO_RPM = 30.0 / math.pi
# The one-panel step (`_one_panel`): Gauss-Legendre, no ends needed. The
# inertia's torque grows faster towards D = 0 than the load's (cos b / D): a
# larger bound on the ellipse, so more digits asked of the same estimate.
_GAUSS_DIGITS = 12.0 * math.log(10.0)
_GAUSS_DIGITS_INERTIA = 14.0 * math.log(10.0)
_INERTIA_GAUSS_REACH = 1.0
_MAX_GAUSS = 6


class LifeRule(NamedTuple):
    rated_torque: float  # T_r, N.m
    constant: float  # K, h rpm deg
    exponent: float  # p
    min_angle: float  # A_min, rad


def bearing_forces(input_torque, input_moment, output_moment, load_torque, radius):
    """(input, output) yoke's trunnion bearing force, N."""
    half = 0.5 / radius
    return (
        math.hypot(input_torque, input_moment) * half,
        math.hypot(load_torque, output_moment) * half,
    )


def rate_scale(rule: LifeRule) -> float:
    """1/L_h per (rad x rad/s x (N.m)^p): the rule's constants and units at once."""
    return _RAD_TO_DEG * _RAD_S_TO_RPM / (rule.constant * rule.rated_torque**rule.exponent)


def life_rate(torque: float, speed: float, bend: float, rule: LifeRule) -> float:
    """1 / L_h (1/h) at one instant; 0 at rest or without torque."""
    angle = max(abs(bend), rule.min_angle)
    return rate_scale(rule) * angle * abs(speed) * abs(torque) ** rule.exponent


def compensated_add(total: float, error: float, term: float) -> tuple[float, float]:
    """Neumaier's sum: (total + term, its rounding carried), so a long run's
    damage drifts by no more than one rounding."""
    new = total + term
    if abs(total) >= abs(term):
        error += (total - new) + term
    else:
        error += (term - new) + total
    return new, error


def rule_of(model) -> LifeRule:
    """The rule from a joint model's parameters (`rated_torque`, `life_*`)."""
    return LifeRule(
        model.rated_torque, model.life_constant, model.life_exponent, model.life_min_angle
    )


def _one_panel(rule: LifeRule, h, psi, b, w1, a1, rb, ab, inertia, load):
    """The common step, without kinks and short enough for one panel, summed in
    one loop (what `life_increment` would do, without its machinery); None
    when the step has a kink, needs several panels or the torque changes sign."""
    min_angle = rule.min_angle
    end = b + h * (rb + 0.5 * ab * h)
    if ab and 0.0 < -rb / ab < h:
        return None  # the bend turns inside: the general path
    if (b > min_angle) != (end > min_angle) or (b < -min_angle) != (end < -min_angle):
        return None  # the bend crosses the floor
    if a1 and 0.0 < -w1 / a1 < h:
        return None
    massless = not (inertia[0] or inertia[1] or inertia[2])
    peak = max(abs(b), abs(end))
    reach = math.acosh(1.0 / math.sin(peak)) if peak > 1e-3 else FLAT_REACH
    if not massless:
        # The inertia's torque varies twice a turn even at no bend: its own scale.
        reach = min(reach, _INERTIA_GAUSS_REACH)
    points = _gauss_points(h, w1, a1, reach, _GAUSS_DIGITS if massless else _GAUSS_DIGITS_INERTIA)
    if not points:
        return None
    I1, I2, I3 = inertia
    p = rule.exponent
    total = 0.0
    low, high = math.inf, 0.0
    for u, w in gauss_unit_rule(points):
        t = u * h
        speed = w1 + a1 * t
        bend = b + t * (rb + 0.5 * ab * t)
        torque = input_torque(
            psi + t * (w1 + 0.5 * a1 * t), bend, speed, a1, rb + ab * t, ab, I1, I2, I3, load
        )
        if not massless:
            low, high = min(low, torque), max(high, torque)
        angle = abs(bend)
        total += w * (angle if angle > min_angle else min_angle) * abs(speed) * abs(torque) ** p
    # The inertia's torque may change sign: the nodes must show it far from zero
    # (one sign, spread below its smallest size), else the general path looks.
    if not massless and (not (low > 0.0 or high < 0.0) or high - low > min(abs(low), abs(high))):
        return None
    return total * h


def _gauss_points(h, w1, a1, reach, digits):
    """Gauss-Legendre points for the step as one panel (Bernstein-ellipse bound
    as `_nodes_for`, `digits` the log of the accuracy asked), or 0 if it needs
    more than `_MAX_GAUSS`."""
    fastest = max(abs(w1), abs(w1 + a1 * h))
    acc = abs(a1)
    if acc:
        tau = 2.0 * reach / (fastest + math.sqrt(fastest * fastest + 2.0 * acc * reach))
    elif fastest:
        tau = reach / fastest
    else:
        return 2
    points = math.ceil(0.5 * digits / math.asinh(2.0 * tau / h))
    return max(points, 2) if points <= _MAX_GAUSS else 0


def step_damage(rule: LifeRule, h, psi, b, w1, a1, rb, ab, inertia, load) -> float:
    """Miner's damage of a joint over a step of `h` s from input-pin angle `psi`
    (the joint's inputs held or ramped over the step as it steps them)."""
    fast = _one_panel(rule, h, psi, b, w1, a1, rb, ab, inertia, load)
    if fast is not None:
        return fast * rate_scale(rule) / 3600.0
    torque_at = torque_over_step(psi, b, w1, a1, rb, ab, inertia, load)
    total = life_increment(torque_at, h, w1, a1, b, rb, ab, inertia, rule.min_angle, rule.exponent)
    return total * rate_scale(rule) / 3600.0


_SPRING_FIELDS = tuple(
    JointResponse._fields.index(name)
    for name in ("input_torque", "speed_ratio", "cardan_error", "output_speed")
)


def step_damage_loaded(rule: LifeRule, h, psi, b, w1, a1, rb, ab, inertia, load_at) -> float:
    """`step_damage` with a load that follows the joint's motion over the step (a
    spring at the output): `load_at(t, cardan_error, output_speed)`, N.m. T1 is
    affine in the load with slope cos b / D (the speed ratio), so one kernel
    call per node gives both the kinematics the load needs and the torque."""
    I1, I2, I3 = inertia

    def torque_at(t):
        r = kernel(
            math, psi + t * (w1 + 0.5 * a1 * t), b + t * (rb + 0.5 * ab * t), w1 + a1 * t, a1,
            rb + ab * t, ab, I1, I2, I3, 0.0, 1.0,
        )  # fmt: skip
        free, ratio, error, speed = (r[i] for i in _SPRING_FIELDS)
        return free + ratio * load_at(t, error, speed)

    # A load that follows the motion can turn the torque over, whatever the cross.
    total = life_increment(
        torque_at, h, w1, a1, b, rb, ab, (*inertia, 1.0), rule.min_angle, rule.exponent
    )
    return total * rate_scale(rule) / 3600.0


def life_outputs(
    rule: LifeRule, radius, consumed, torque, input_moment, output_moment, load, speed, bend
) -> tuple[float, float, float, float]:
    """(input_bearing_force, output_bearing_force, life_rate, life_consumed) now."""
    return (
        *bearing_forces(torque, input_moment, output_moment, load, radius),
        life_rate(torque, speed, bend, rule),
        consumed,
    )
