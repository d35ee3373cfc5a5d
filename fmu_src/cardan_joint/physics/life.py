"""Trunnion bearing loads and catalogue life of a Cardan joint (docs/life.md).

Bearing force: yoke k acts on the cross with a torque tau_k normal to its pin,
carried by its two trunnions at radius r, so each of those needle bearings
carries |tau_k| / (2 r); |tau_1|^2 = T1^2 + C1^2 (its shaft-axis part and the
secondary couple), |tau_2|^2 = T_L^2 + C2^2.

Life: the joint makers' rule for needle-bearing B10 life,
L_h = K / (A n) (T_r / |T|)^p hours, A = max(|b|, A_min) in degrees, n = |w1|
in rpm, T = T1; damage is Miner's sum of dt / (3600 L_h). Over a step whose
inputs are polynomial (speed and bend at constant acceleration, load held)
the rate is known in closed form at every instant: `life_integral` takes
its integral, cut at the step's events.
Pure Python, standard library only.
"""

import math
from typing import NamedTuple

from .life_integral import FLAT_REACH, singularity_time, step_integral
from .life_torque import joint_torque

_RAD_TO_DEG = 180.0 / math.pi
_RAD_S_TO_RPM = 30.0 / math.pi


class LifeRule(NamedTuple):
    """A joint's life rule (`life_rule` makes one): its parameters and the
    scale they give the rate, computed once per rule, not at every step."""

    rated_torque: float  # T_r, N.m
    constant: float  # K, h rpm deg
    exponent: float  # p
    min_angle: float  # A_min, rad
    scale: float  # 1/L_h per (rad x rad/s x (N.m)^p): `rate_scale`'s


def bearing_forces(input_torque, input_moment, output_moment, load_torque, radius):
    """(input, output) yoke's trunnion bearing force, N."""
    half = 0.5 / radius
    return (
        magnitude(input_torque, input_moment) * half,
        magnitude(load_torque, output_moment) * half,
    )


def magnitude(x, y):
    """sqrt(x^2 + y^2). Not `math.hypot`: CPython's is correctly rounded, the C
    library's is not, so generated C would differ by an ulp; a square root of a
    sum of squares rounds alike in both. The inputs' ranges keep the squares
    far from overflow (|x|, |y| < 1e150)."""
    return math.sqrt(x * x + y * y)


def rate_scale(rated_torque: float, constant: float, exponent: float) -> float:
    """1/L_h per (rad x rad/s x (N.m)^p): the rule's constants and units at once."""
    return _RAD_TO_DEG * _RAD_S_TO_RPM / (constant * rated_torque**exponent)


def life_rule(rated_torque: float, constant: float, exponent: float, min_angle: float) -> LifeRule:
    """The rule of these parameters, with its `rate_scale`."""
    scale = rate_scale(rated_torque, constant, exponent)
    return LifeRule(rated_torque, constant, exponent, min_angle, scale)


# The rule of a model whose life is off or whose parameters cannot run: a
# number for its state, never read.
NO_RULE = life_rule(1.0, 1.0, 1.0, 0.0)


def life_rate(torque: float, speed: float, bend: float, rule: LifeRule) -> float:
    """1 / L_h (1/h) at one instant; 0 at rest or without torque."""
    angle = max(abs(bend), rule.min_angle)
    return rule.scale * angle * abs(speed) * abs(torque) ** rule.exponent


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
    return life_rule(
        model.rated_torque, model.life_constant, model.life_exponent, model.life_min_angle
    )


def singularity_reach(peak):
    """How far the torque's singularities lie in imaginary input angle at a real
    bend of at most `peak` (up to pi/2, as the joint's limits keep it)."""
    return _reach_of_sine(math.sin(peak))


def _reach_of_sine(sine):
    """A lower bound on |Im psi| where the torque is singular while |sin b| <=
    `sine`: D = 1 - sin^2 b cos^2 psi vanishes only where |cos psi| |sin b| =
    1, and |cos psi| <= cosh(Im psi); below 1e-3 capped at FLAT_REACH."""
    if sine <= 1e-3:
        return FLAT_REACH
    return math.acosh(1.0 / sine) if sine < 1.0 else 0.0


def step_reach(h, w1, a1, b, rb, ab):
    """`singularity_reach` over a step of `h` s, speed w1 + a1 t and bend b +
    rb t + ab t^2 / 2, where the bend at a complex time moves too. Within d of
    a point t0 of the step the bend moves by at most e = |b'(t0)| d + |ab|
    d^2 / 2, so that |sin b| <= sin(peak) + e cosh(e) <= sin(peak) + e (1 +
    e^2) (the cosine's bound along the way, e < 1): the reach r_e of that
    sine holds as far as psi moves less, |w| d + |a1| d^2 / 2 < r_e
    (`life_integral.singularity_time`). e is the move over the held bend's
    tau (larger than the answer's), at most a quarter of 1 - sin(peak); where
    that cap binds, the reach is also cut to psi's move while e is reached."""
    peak = peak_bend(h, b, rb, ab)
    sine = math.sin(peak)
    reach = _reach_of_sine(sine)
    if rb == 0.0 and ab == 0.0:
        return reach
    tau = singularity_time(w1, a1, h, reach)
    if tau == math.inf:  # the input angle stands still: no rate to integrate
        return reach
    turn = max(abs(rb), abs(rb + ab * h))
    wobble = min(tau * (turn + 0.5 * abs(ab) * tau), 0.25 * (1.0 - sine))
    reach = _reach_of_sine(sine + wobble * (1.0 + wobble * wobble))
    within = 2.0 * wobble / (turn + math.sqrt(turn * turn + 2.0 * abs(ab) * wobble))
    fastest = max(abs(w1), abs(w1 + a1 * h))
    return min(reach, within * (fastest + 0.5 * abs(a1) * within))


def peak_bend(h, b, rb, ab):
    """The largest |bend| over a step of `h` s from b at rate rb, acceleration ab."""
    peak = max(abs(b), abs(b + h * (rb + 0.5 * ab * h)))
    if ab != 0.0 and 0.0 < -rb / ab < h:
        peak = max(peak, abs(b - 0.5 * rb * rb / ab))
    return peak


def step_damage(rule: LifeRule, h, psi, b, w1, a1, rb, ab, inertia, load) -> float:
    """Miner's damage of a joint over a step of `h` s from input-pin angle `psi`
    (the joint's inputs held or ramped over the step as it steps them)."""
    step = (psi, b, w1, a1, rb, ab, *inertia, load, math.sin(b), math.cos(b))
    return _damage(rule, joint_torque, step, h, b, w1, a1, rb, ab)


def _damage(rule: LifeRule, torque_at, step, h, b, w1, a1, rb, ab) -> float:
    """Miner's damage over a step of `h` s of the torque `torque_at(t, step)`
    (`life_integral.step_integral`'s arguments)."""
    total = step_integral(
        torque_at, step, h, w1, a1, b, rb, ab, rule.min_angle, rule.exponent,
        step_reach(h, w1, a1, b, rb, ab),
    )  # fmt: skip
    return total * rule.scale / 3600.0


def step_damage_loaded(
    rule: LifeRule, h, psi, b, w1, a1, rb, ab, inertia, torque_at, load
) -> float:
    """`step_damage` with a load that follows the joint's motion over the step (a
    spring at the output): `torque_at(t, step)` gives (T1, input speed) t s into
    it, `step` = (psi, b, w1, a1, rb, ab, I1, I2, I3, *load, sin b, cos b) at
    the step's start, `load` the parameters of the load's law (the spring's
    start). The generated step and the Python one both come here: same bits."""
    step = (psi, b, w1, a1, rb, ab, *inertia, *load, math.sin(b), math.cos(b))
    return _damage(rule, torque_at, step, h, b, w1, a1, rb, ab)


def life_outputs(
    rule: LifeRule, radius, consumed, torque, input_moment, output_moment, load, speed, bend
) -> tuple[float, float, float, float]:
    """(input_bearing_force, output_bearing_force, life_rate, life_consumed) now."""
    return (
        *bearing_forces(torque, input_moment, output_moment, load, radius),
        life_rate(torque, speed, bend, rule),
        consumed,
    )
