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

The joints of a chain share the march (`step_integrals`): each panel's
nodes serve every joint's integrand, so the chain is evaluated once per node
for all of them (`life_nodes`); a panel is taken when every joint's bound
holds, with the most points any joint asks for, and cut at the first zero of
any joint's torque. A single joint is the case N = 1 (`step_integral`).

Pure Python over floats and tuples, no state; the torques are a module-level
function `torques_at(t, step)` -> (T_1, w_1, ..., T_N, w_N), each joint's
torque and input speed t s into the step.
"""

import math

from .life_nodes import (
    PANEL_FIELDS,
    divides_at,
    filled,
    panel,
    scales_raised,
    torque_of,
    totals_added,
    verdict,
)
from .life_panel import (
    error_budget,
    longest_panel,
    may_vanish,
    node_time,
    points_for,
    rule_sizing,
    singular_log_rho,
    substitution_power,
)
from .quadrature import MAX_POINTS, node_of

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
# Two joints' zeros this close, against the panel that shows them, are one:
# a chain whose torques are all proportional to its load has its joints'
# zeros at one instant, which their rounding spreads by a few 1e-17 s, and
# its nodes show them all at once. A joint substituted at a zero this far
# from its own errs by far less than the bound (its torque's sign differs
# only below the first node's u^q).
_SAME_ZERO = 1e-12


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


def next_kink(t, h, w1, a1, bends, rb, ab, min_angle):
    """The first point after t where an angle or the speed factor has a kink:
    the speed's zero, a bend (`bends[k]` + rb t + ab t^2 / 2) crossing
    +-A_min; else the step's end h."""
    end = _first_root_after(t, h, w1, a1, 0.0)
    for k in range(len(bends)):
        end = _first_root_after(t, end, bends[k] - min_angle, rb, 0.5 * ab)
        end = _first_root_after(t, end, bends[k] + min_angle, rb, 0.5 * ab)
    return end


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


def _root(torques_at, step, joint: int, a, b, fa, fb):
    """A sign change of `joint`'s torque in (a, b), fa and fb of opposite signs, to
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
        fb = torque_of(torques_at(b, step), joint)
    return b


def _root_by(torques_at, step, joint: int, a, fa, b):
    """The zero of `joint`'s torque between a (T = fa there) and b, if T's
    sign differs at b; else -1."""
    fb = torque_of(torques_at(b, step), joint)
    if fa != 0.0 and fb != 0.0 and (fa < 0.0) != (fb < 0.0):
        if a > b:
            return _root(torques_at, step, joint, b, a, fb, fa)
        return _root(torques_at, step, joint, a, b, fa, fb)
    return -1.0


def _zero_in(torques_at, step, joint: int, lo, hi, zero: int, own: int, q, points: int,
             weighted: bool, change: int):  # fmt: skip
    """A zero of `joint`'s torque in (lo, hi), the panel's (substituted as
    `zero`; `own` is `zero` where the substitution's zero is the joint's,
    else 0; its nodes Gauss-Jacobi's if `weighted`): between nodes change - 1
    and `change` if they differ in sign, else between an end (not the joint's
    known zero) and its nearest node; -1.0 if neither shows one."""
    first = node_time(lo, hi, node_of(points, 0, weighted), zero, q)
    if change != 0:
        before = node_time(lo, hi, node_of(points, change - 1, weighted), zero, q)
        return _root_by(
            torques_at, step, joint, before, torque_of(torques_at(before, step), joint),
            node_time(lo, hi, node_of(points, change, weighted), zero, q),
        )  # fmt: skip
    last = node_time(lo, hi, node_of(points, points - 1, weighted), zero, q)
    # The node nearest each end: the first in u, except on a panel substituted at hi.
    near_lo, near_hi = (last, first) if zero < 0 else (first, last)
    if own <= 0:
        found = _root_by(torques_at, step, joint, lo, torque_of(torques_at(lo, step), joint),
                         near_lo)  # fmt: skip
        if found >= 0.0:
            return found
    if own >= 0:
        return _root_by(torques_at, step, joint, hi, torque_of(torques_at(hi, step), joint),
                        near_hi)  # fmt: skip
    return -1.0


def _first_zero(torques_at, step, values, failing: int, lo, hi, zero: int, divides: int, q,
                points: int, weighted: bool):  # fmt: skip
    """(the first zero in (lo, hi) of a torque whose joint fails on the panel
    and whose values show one, the joints whose zero it is, one bit each);
    (-1.0, 0) if none shows one."""
    first, joints = -1.0, 0
    for k in range(len(values) // PANEL_FIELDS):
        change = values[PANEL_FIELDS * k + 1]
        coefficients = values[PANEL_FIELDS * k + 2 : PANEL_FIELDS * (k + 1)]
        if divides_at(failing, k) and (change != 0 or may_vanish(coefficients)):
            own = zero if divides_at(divides, k) else 0
            root = _zero_in(torques_at, step, k, lo, hi, zero, own, q, points, weighted, change)
            if root > lo:
                same = _SAME_ZERO * (hi - lo)
                if first < 0.0 or root < first - same:
                    first, joints = root, 1 << k
                elif root <= first + same:
                    first, joints = min(first, root), joints | (1 << k)
    return first, joints


def step_integrals(torques_at, step, h, w1, a1, bends, rb, ab, min_angle, p, reach):
    """Each joint's integral over a step of `h` s of A_k(t) |w_k(t)|
    |T_k(t)|^p, A_k = max(|b_k(t)|, `min_angle`): the life rate's variable
    part (`life.step_damage` scales it), for the joints of a chain at once.

    `torques_at(t, step)`: (T_1, w_1, ..., T_N, w_N) t s into the step; joint
    k's bend `bends[k]` + rb t + ab t^2 / 2 as the joints step it; w1 + a1 t
    the input speed, which places the speed's zero and, with `reach` (the
    torques' singularities' imaginary input angle, `life.singularity_reach`),
    sizes the panels."""
    tau = singularity_time(w1, a1, h, reach)
    q = substitution_power(p)
    gamma = q * (p + 1.0) - 1.0
    budget = error_budget(p)
    joints = len(bends)
    # zero_lo, zero_end: the joints (one bit each) whose torque's zero is at t,
    # at `end`. What each joint's bound is asked against: `scales_raised`.
    totals = filled(bends, 0.0)
    scales = filled(bends, -1.0)
    t, zero_lo = 0.0, 0
    end, zero_end = next_kink(0.0, h, w1, a1, bends, rb, ab, min_angle), 0
    length, points = h, 0
    for _ in range(_MAX_ATTEMPTS):
        if t >= h:
            return totals
        hi = t + length
        if hi >= end or end - hi < 0.25 * length:
            hi = end
        zero = 1 if zero_lo != 0 else -1 if zero_end != 0 and hi == end else 0
        if zero_lo != 0 and zero_end != 0 and hi == end:
            # A panel substitutes at one end only; two zeros an ulp apart leave
            # no middle: the ulp between them is taken plainly (its share is nil).
            middle = 0.5 * (t + end)
            hi, zero = (middle, 1) if middle > t else (end, 0)
        divides = zero_lo if zero > 0 else zero_end if zero < 0 else 0
        weighted, stretch, degree, sized = rule_sizing(zero, divides, joints, q, gamma, budget)
        longest = longest_panel(tau, sized, degree, stretch)
        if hi - t > longest:
            hi = t + longest
            zero = 1 if zero_lo != 0 else 0
            divides = zero_lo if zero > 0 else 0
            weighted, stretch, degree, sized = rule_sizing(zero, divides, joints, q, gamma, budget)
        singular = singular_log_rho(hi - t, tau, stretch)
        n = min(max(points, points_for(singular, sized, degree)), MAX_POINTS)
        values = panel(torques_at, step, t, hi, zero, divides, q, n, weighted, bends, rb, ab,
                       min_angle, p)  # fmt: skip
        scales = scales_raised(scales, totals, values)
        carried = q - 1.0 if zero != 0 else 0.0
        failing, wanted = verdict(values, scales, n, sized, degree, carried, singular, divides)
        if failing == 0 or hi - t <= _SHORTEST * h:
            totals = totals_added(totals, values)
            # The next panel starts from this one's points and twice its
            # length: a piece's panels are alike.
            length = 2.0 * (hi - t)
            t, zero_lo = hi, divides if zero < 0 else 0
            if t == end:  # a new piece: its panels start from the longest again
                end, zero_end = next_kink(t, h, w1, a1, bends, rb, ab, min_angle), 0
                length, points = h, 0
            continue
        if wanted != 0:
            length, points = hi - t, wanted
            continue
        root, zeros = _first_zero(torques_at, step, values, failing, t, hi, zero, divides, q, n,
                                  weighted)  # fmt: skip
        if root > t:
            end, zero_end = root, zeros
        else:
            length = 0.5 * (hi - t)
    # A step over thousands of turns: what is left in one panel, less exactly.
    if t < h:
        totals = totals_added(
            totals,
            panel(torques_at, step, t, h, 0, 0, q, MAX_POINTS, False, bends, rb, ab, min_angle, p),
        )
    return totals


def step_integral(torque_at, step, h, w1, a1, b, rb, ab, min_angle, p, reach):
    """The integral over a step of `h` s of A(t) |w(t)| |T(t)|^p, A = max(|b(t)|,
    `min_angle`) for one joint: `step_integrals` with N = 1, `torque_at(t,
    step)` giving (T, w) t s into the step; the bend b + rb t + ab t^2 / 2."""
    return step_integrals(torque_at, step, h, w1, a1, (b,), rb, ab, min_angle, p, reach)[0]
