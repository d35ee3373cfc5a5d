"""The life rate's integral over one step (docs/life.md, "Exact over each step").

The integrand A(t) |w(t)| |T(t)|^p is smooth except at the step's events: the
speed's zero and the bend crossing +-A_min (closed forms) and the torque's
zeros (located to the last bits as the panels meet them). The step is cut at
each event and every piece between them is covered by Gauss-Legendre panels
(`life_panel`), marching from its start: a panel whose error bound asks for
more points than it has is taken again with them, or cut at the torque's
sign change it shows, or halved. So a piece costs one panel unless it is
longer than the torque's singularities' reach, and each event costs its
location and a few panels more.

Pure Python over floats and tuples, no state; the torque is a module-level
function `torque_at(t, step)` -> (T, w), the torque and the speed t s into
the step.
"""

import math

from .life_panel import (
    error_budget,
    log_rho_required,
    longest_panel,
    may_vanish,
    node_time,
    panel,
    points_for,
    singular_log_rho,
    substitution_power,
    zero_free_log_rho,
    zero_free_on,
)
from .quadrature import GAUSS_NODES, MAX_POINTS

# Below 1 mrad of bend the torque's singularities are practically out of reach.
FLAT_REACH = math.acosh(1e3)
# Panels tried per step and root-finder steps per zero: a step over thousands
# of turns ends with one panel for what is left, less exactly (docs/life.md).
_MAX_ATTEMPTS = 4096
_ROOT_STEPS = 200
# Brent's bracket, relative and absolute: two ulps of the zero's time.
_ROOT_TOLERANCE = 2.0 * 2.220446049250313e-16
_TINY_TIME = 1e-300
# A panel this short against the step is taken as it is.
_SHORTEST = 1e-13


def _first_root_after(t, limit, c0, c1, c2):
    """The smallest root of c0 + c1 x + c2 x^2 in (t, limit), else `limit`."""
    if c2 == 0.0:
        if c1 == 0.0:
            return limit
        first, second = -c0 / c1, limit
    else:
        disc = c1 * c1 - 4.0 * c2 * c0
        if disc < 0.0:
            return limit
        q = -0.5 * (c1 + math.copysign(math.sqrt(disc), c1))
        if q == 0.0:
            first, second = 0.0, limit
        else:
            first, second = q / c2, c0 / q
    if t < first < limit:
        limit = first
    if t < second < limit:
        limit = second
    return limit


def next_kink(t, h, w1, a1, b, rb, ab, min_angle):
    """The first point after t where the angle or the speed factor has a kink:
    the speed's zero, the bend crossing +-A_min; else the step's end h."""
    end = _first_root_after(t, h, w1, a1, 0.0)
    end = _first_root_after(t, end, b - min_angle, rb, 0.5 * ab)
    return _first_root_after(t, end, b + min_angle, rb, 0.5 * ab)


def singularity_time(w1, a1, h, reach):
    """How far in time the torque's singularities lie from any point of the
    step: |w| tau + |a1| tau^2 / 2 = reach at the fastest speed of the step."""
    fastest = max(abs(w1), abs(w1 + a1 * h))
    acc = abs(a1)
    if acc != 0.0:
        return 2.0 * reach / (fastest + math.sqrt(fastest * fastest + 2.0 * acc * reach))
    if fastest != 0.0:
        return reach / fastest
    return math.inf


def _root(torque_at, step, a, b, fa, fb):
    """A sign change of the torque in (a, b), fa and fb of opposite signs, to
    the last bits: Brent's method (inverse quadratic and secant steps, bisection
    when they stall), which shrinks the bracket to a few ulps in about half the
    evaluations regula falsi takes, as its steps never fall below that width."""
    c, fc = a, fa
    d, e = b - a, b - a
    for _ in range(_ROOT_STEPS):
        if fb == 0.0:
            return b
        if (fb < 0.0) == (fc < 0.0):
            c, fc = a, fa
            d, e = b - a, b - a
        if abs(fc) < abs(fb):
            a, b, c, fa, fb, fc = b, c, b, fb, fc, fb
        tolerance = _ROOT_TOLERANCE * abs(b) + _TINY_TIME
        half = 0.5 * (c - b)
        if abs(half) <= tolerance:
            return b
        if abs(e) < tolerance or abs(fa) <= abs(fb):
            d, e = half, half
        else:
            s = fb / fa
            if a == c:
                p, q = 2.0 * half * s, 1.0 - s
            else:
                q, r = fa / fc, fb / fc
                p = s * (2.0 * half * q * (q - r) - (b - a) * (r - 1.0))
                q = (q - 1.0) * (r - 1.0) * (s - 1.0)
            if p > 0.0:
                q = -q
            else:
                p = -p
            if 2.0 * p < min(3.0 * half * q - abs(tolerance * q), abs(e * q)):
                e, d = d, p / q
            else:
                d, e = half, half
        a, fa = b, fb
        b += d if abs(d) > tolerance else math.copysign(tolerance, half)
        fb = torque_at(b, step)[0]
    return b


def _root_by(torque_at, step, a, fa, b):
    """The zero between a (T = fa there) and b, if T's sign differs at b; else -1."""
    fb = torque_at(b, step)[0]
    if fa != 0.0 and fb != 0.0 and (fa < 0.0) != (fb < 0.0):
        if a > b:
            return _root(torque_at, step, b, a, fb, fa)
        return _root(torque_at, step, a, b, fa, fb)
    return -1.0


def _zero_in(torque_at, step, lo, hi, zero: int, q, points: int, change: int):
    """A zero of T in (lo, hi), the panel's: between nodes change - 1 and
    `change` if they differ in sign, else between an end (not a known zero) and
    its nearest node; -1.0 if neither shows one."""
    first = node_time(lo, hi, GAUSS_NODES[points][0], zero, q)
    if change != 0:
        before = node_time(lo, hi, GAUSS_NODES[points][change - 1], zero, q)
        return _root_by(
            torque_at, step, before, torque_at(before, step)[0],
            node_time(lo, hi, GAUSS_NODES[points][change], zero, q),
        )  # fmt: skip
    last = node_time(lo, hi, GAUSS_NODES[points][points - 1], zero, q)
    # The node nearest each end: the first in u, except on a panel substituted at hi.
    near_lo, near_hi = (last, first) if zero < 0 else (first, last)
    if zero <= 0:
        found = _root_by(torque_at, step, lo, torque_at(lo, step)[0], near_lo)
        if found >= 0.0:
            return found
    if zero >= 0:
        return _root_by(torque_at, step, hi, torque_at(hi, step)[0], near_hi)
    return -1.0


def step_integral(torque_at, step, h, w1, a1, b, rb, ab, min_angle, p, reach):
    """The integral over a step of `h` s of A(t) |w(t)| |T(t)|^p, A = max(|b(t)|,
    `min_angle`): the life rate's variable part (`life.step_damage` scales it).

    `torque_at(t, step)`: (T, w) t s into the step; the bend b + rb t + ab t^2 / 2
    as the joint steps it; w1 + a1 t the input speed, which places the speed's
    zero and, with `reach` (the torque's singularities' imaginary input angle,
    `life.singularity_reach`), sizes the panels."""
    tau = singularity_time(w1, a1, h, reach)
    q = substitution_power(p)
    gamma = q * (p + 1.0) - 1.0
    budget = error_budget(p)
    total, t, zero_lo = 0.0, 0.0, False
    end, zero_end = next_kink(0.0, h, w1, a1, b, rb, ab, min_angle), False
    length, points = h, 0
    # What the bound is asked against: the step's integral, from below (a
    # quarter of the first panel's value, then what the accepted panels sum;
    # every panel's part is positive). A panel that adds little to it may err
    # more against its own.
    scale = -1.0
    for _ in range(_MAX_ATTEMPTS):
        if t >= h:
            return total
        hi = t + length
        if hi >= end or end - hi < 0.25 * length:
            hi = end
        zero = 1 if zero_lo else -1 if zero_end and hi == end else 0
        if zero_lo and zero_end and hi == end:
            # A panel substitutes at one end only; two zeros an ulp apart leave
            # no middle: the ulp between them is taken plainly (its share is nil).
            middle = 0.5 * (t + end)
            hi, zero = (middle, 1) if middle > t else (end, 0)
        stretch, degree = (q, gamma) if zero != 0 else (1.0, 0.0)
        longest = longest_panel(tau, budget, degree, stretch)
        if hi - t > longest:
            hi = t + longest
            zero = 1 if zero_lo else 0
            stretch, degree = (q, gamma) if zero != 0 else (1.0, 0.0)
        singular = singular_log_rho(hi - t, tau, stretch)
        n = min(max(points, points_for(singular, budget, degree)), MAX_POINTS)
        value, change, a0, a1, a2, a3, a_last = panel(
            torque_at, step, t, hi, zero, q, n, b, rb, ab, min_angle, p
        )
        coefficients = (a0, a1, a2, a3, a_last)
        if scale < 0.0:
            scale = 0.25 * value
        scale = max(scale, total)
        share = math.log(scale / value) if scale > value > 0.0 else 0.0
        required = log_rho_required(n, budget - share, degree)
        if (
            change == 0
            and required <= singular
            and (value == 0.0 or zero_free_on(required, coefficients, n, zero != 0))
        ) or hi - t <= _SHORTEST * h:
            total += value
            # The next panel starts from this one's points and twice its
            # length: a piece's panels are alike.
            length = 2.0 * (hi - t)
            t, zero_lo = hi, zero < 0
            if t == end:  # a new piece: its panels start from the longest again
                end, zero_end = next_kink(t, h, w1, a1, b, rb, ab, min_angle), False
                length, points = h, 0
            continue
        if change == 0 and n < MAX_POINTS:
            # The points T's zeros and its resolution ask for: if its zeros
            # allow the largest rule, as many as they ask, or twice as many
            # while the highest coefficient is not yet resolved.
            low, top = zero_free_log_rho(coefficients, n, zero != 0)
            own = points_for(min(singular, low), budget - share, degree)
            if own <= MAX_POINTS:
                needed = points_for(min(singular, low, top), budget - share, degree)
                resolved = needed if needed <= MAX_POINTS else 2 * n
                length, points = hi - t, min(MAX_POINTS, max(own, resolved, n + 1))
                continue
        root = -1.0
        if change != 0 or may_vanish(coefficients):
            root = _zero_in(torque_at, step, t, hi, zero, q, n, change)
        if root > t:
            end, zero_end = root, True
        else:
            length = 0.5 * (hi - t)
    # A step over thousands of turns: what is left in one panel, less exactly.
    if t < h:
        total += panel(torque_at, step, t, h, 0, q, MAX_POINTS, b, rb, ab, min_angle, p)[0]
    return total
