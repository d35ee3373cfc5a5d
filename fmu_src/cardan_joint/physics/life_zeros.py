"""The torques' zeros a panel of the life integral shows (`life_integral`;
docs/life.md, "Exact over each step"), each located as exactly as the panel
substituted at it needs.

A panel that fails at a joint's torque's sign change between two of its
nodes, or whose values let the torque vanish between an end and its nearest
node, is cut at the zero there: Brent's method from the two torques the panel
already has (`life_nodes.PANEL_FIELDS`), or from one of them and the end's.
Every failing joint's zero is located; the march is cut at the first and
keeps the next for later.

What the panel needs: substituted at z where T(z) = c, not 0, it still
integrates A |w| |T|^p exactly as a function, only not one of the smoothness
its bound assumes, that of |T - c|^p (whose zero is z). The two differ by at
most p |c| (|T| + |c|)^(p-1) A |w|, which the integral and the rule alike
(its weights positive, the bound smooth in u) take to about p |c| int A |w|
(|T| + |c|)^(p-1) each: by Hoelder's inequality, 2 p |c| / M_p of the step's
integral, M_p the step's p-mean torque (int A |w| |T|^p / int A |w|)^(1/p).
The search ends once |T| is `SETTLED_ZERO` of the larger torque it starts
from, at nodes of the step, of M_p's order (1.55 M_p where T is linear
across the step): 1e-12 of the step's integral, below the least a panel may
err by (8e-12 of the step's, `life_panel.target_share`) and far below what its
bound, loose by orders, lets it err. Where the torque's rounding hides its
zero above that share, the search ends within the rounding, which the
integrand carries at every node anyway.
"""

import math

from .life_nodes import COEFFICIENTS, PANEL_FIELDS, divides_at, torque_of
from .life_panel import may_vanish, node_time
from .quadrature import node_of

# Root-finder steps per zero.
_ROOT_STEPS = 200
# Brent's bracket at the least, relative and absolute: two ulps of the zero's time.
_ROOT_TOLERANCE = 2.0 * 2.220446049250313e-16
_TINY_TIME = 1e-300
# A zero is located once its torque is within this share of the larger of
# the two the search starts from (the module's bound), or its bracket within
# half of a quarter of it of the first bracket's width (about the same torque
# where T is nearly linear across that bracket, as between two neighbouring
# nodes of a panel whose cubic fits; more where T curves strongly).
SETTLED_ZERO = 1e-13
_SETTLED_BRACKET = 0.25 * SETTLED_ZERO
# A step from the best point this small against the first bracket is where T
# is linear to about this share, so an interpolation step shrinks |T| by as
# much: where |T| did not shrink, the torque's rounding hides the zero, and
# the best point's torque is that rounding's size (`_root`).
_ROUNDING_STEP = 1e-6
# Two joints' zeros this close, against the panel that shows them, are one:
# a chain whose torques are all proportional to its load has its joints'
# zeros at one instant, which their rounding and their searches' settled
# share (`SETTLED_ZERO` of a bracket within the panel each) spread, and its
# nodes show them all at once; a chain at a steady speed has them a rounding
# apart (2e-14 s at 30 rad/s), and a torque that starts from its rounding at
# a dead centre has its zero that close before the step (`_root_by`). A joint
# substituted at a zero this far from its own errs by far less than the
# bound: its torque's sign differs only below the first node's u^q, at least
# 4e-8 of the panel (the largest rule's first node, cubed).
SAME_ZERO = 1e-10


def _root(torques_at, step, joint: int, a, b, fa, fb):
    """A sign change of `joint`'s torque in (a, b), fa and fb of opposite signs,
    as exactly as the panel substituted at it needs (`SETTLED_ZERO`): Brent's
    method (inverse quadratic and secant steps, bisection when they stall),
    which ends at the first torque that small, or where the bracket is
    settled, or where a step within T's linear reach left |T| no smaller (the
    torque's rounding hides the zero: the best point, inside the bracket)."""
    settled = SETTLED_ZERO * max(abs(fa), abs(fb))
    narrowest = max(_SETTLED_BRACKET * abs(b - a), _TINY_TIME)
    rounding = _ROUNDING_STEP * abs(b - a)
    first, last = min(a, b), max(a, b)
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
        tolerance = max(_ROOT_TOLERANCE * abs(b), narrowest)
        half = 0.5 * (c - b)
        if abs(half) <= tolerance:
            # An end whose torque is within the rounding may stay the best
            # point: the zero is then the other side of the settled bracket.
            return b if first < b < last else c
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
        if abs(fb) <= settled:
            return b
        if abs(fb) >= abs(fa) and abs(b - a) <= rounding and first < a < last:
            return a
    return b


def _root_by(torques_at, step, joint: int, end, node, at_node, same):
    """The zero of `joint`'s torque between a panel's `end` and its `node`
    nearest it (T = `at_node` there), if T's sign differs at the end; the end
    itself where T's line through the two puts a zero within `same` of it
    (`SAME_ZERO`: a torque that vanishes at the end to its rounding); else -1."""
    at_end = torque_of(torques_at(end, step), joint)
    if abs(at_end) * abs(node - end) <= same * abs(at_node - at_end):
        return end
    if at_node != 0.0 and (at_end < 0.0) != (at_node < 0.0):
        if end > node:
            return _root(torques_at, step, joint, node, end, at_node, at_end)
        return _root(torques_at, step, joint, end, node, at_end, at_node)
    return -1.0


def _zero_in(torques_at, step, joint: int, lo, hi, zero: int, own: int, q, points: int,
             weighted: bool, change: int, kept_lo, kept_hi):  # fmt: skip
    """A zero of `joint`'s torque in (lo, hi), the panel's (substituted as
    `zero`; `own` is `zero` where the substitution's zero is the joint's,
    else 0; its nodes Gauss-Jacobi's if `weighted`): between nodes
    change - 1 and `change` if they differ in sign (their torques `kept_lo`,
    `kept_hi`), else between an end (not the joint's known zero) and its
    nearest node (the first node's torque `kept_lo`, the last's `kept_hi`);
    -1.0 if neither shows one."""
    if change != 0:
        before = node_time(lo, hi, node_of(points, change - 1, weighted), zero, q)
        after = node_time(lo, hi, node_of(points, change, weighted), zero, q)
        if before > after:
            return _root(torques_at, step, joint, after, before, kept_hi, kept_lo)
        return _root(torques_at, step, joint, before, after, kept_lo, kept_hi)
    first = node_time(lo, hi, node_of(points, 0, weighted), zero, q)
    last = node_time(lo, hi, node_of(points, points - 1, weighted), zero, q)
    # The node nearest each end: the first in u, except on a panel substituted at hi.
    near_lo, near_hi = (last, first) if zero < 0 else (first, last)
    at_lo, at_hi = (kept_hi, kept_lo) if zero < 0 else (kept_lo, kept_hi)
    if own <= 0:
        found = _root_by(torques_at, step, joint, lo, near_lo, at_lo, SAME_ZERO * (hi - lo))
        if found >= 0.0:
            return found
    if own >= 0:
        return _root_by(torques_at, step, joint, hi, near_hi, at_hi, SAME_ZERO * (hi - lo))
    return -1.0


def _earliest(roots, after, same):
    """(the earliest of `roots` past `after`, the joints whose roots lie
    within `same` of it, one bit each); (inf, 0) if none lies past it."""
    first = math.inf
    for k in range(len(roots)):
        if after < roots[k] < first:
            first = roots[k]
    joints = 0
    for k in range(len(roots)):
        if after < roots[k] <= first + same:
            joints = joints | (1 << k)
    return first, joints


def first_zeros(torques_at, step, values, failing: int, lo, hi, zero: int, divides: int, q,
                points: int, weighted: bool):  # fmt: skip
    """(the first zero in (lo, hi] of a torque whose joint fails on the panel
    and whose values show one, the joints whose zero it is, one bit each,
    then the next such zero and its joints, which the march keeps for later;
    then the joints whose torque vanishes at lo itself, whose zero is where
    the panel starts); inf and 0 for a zero none shows."""
    roots = ()  # type: tuple
    starting = 0
    for k in range(len(values) // PANEL_FIELDS):
        change = values[PANEL_FIELDS * k + 1]
        coefficients = values[PANEL_FIELDS * k + COEFFICIENTS : PANEL_FIELDS * (k + 1)]
        root = -1.0
        if divides_at(failing, k) and (change != 0 or may_vanish(coefficients)):
            own = zero if divides_at(divides, k) else 0
            root = _zero_in(torques_at, step, k, lo, hi, zero, own, q, points, weighted, change,
                            values[PANEL_FIELDS * k + 2], values[PANEL_FIELDS * k + 3])  # fmt: skip
            if root == lo:
                starting = starting | (1 << k)
        roots = roots + (root,)
    same = SAME_ZERO * (hi - lo)
    first, joints = _earliest(roots, lo, same)
    second, others = _earliest(roots, first + same, same)
    return first, joints, second, others, starting
