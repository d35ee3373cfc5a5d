"""One panel of the life integral for the N joints of a chain at once
(`life_integral` marches them over a step; docs/life.md, "Exact over each
step"), and each joint's verdict on it (`life_panel`'s bound).

The joints share the panel's nodes: `torques_at(t, step)` gives every joint's
torque and input speed at a node, (T_1, w_1, ..., T_N, w_N), so a chain is
evaluated once per node for all its joints. Each joint keeps its own
integrand A_k |w_k| |T_k|^p, its own Legendre coefficients and its own bound
against its own integral. A panel substituted at some joints' torque zero
(`divides`, one bit per joint) divides only their torques by u^q; to the
others it is a plain change of variable, their torque a smooth function of u.
A single joint (the UniversalJoint) is the case N = 1. Where the panel
divides every joint's torque, it may take the Gauss-Jacobi rule for the
weight u^gamma (`weighted`, `life_panel.rule_sizing`): each joint's rule then
sums q A_k |w_k| |T_k / u^q|^p, and its coefficients are read off the same
values by the Gauss-Jacobi tables.
"""

from .life_panel import (
    log_rho_required,
    node_time,
    points_for,
    power_of,
    target_share,
    weighted_share,
    whole_power,
    zero_free_log_rho,
    zero_free_on,
)
from .quadrature import (
    FIRST_COEFFICIENT,
    GAUSS_WEIGHTS,
    JACOBI_FIRST,
    JACOBI_LAST,
    JACOBI_MEAN,
    JACOBI_SECOND,
    JACOBI_THIRD,
    JACOBI_WEIGHTS,
    JACOBI_ZEROTH,
    LAST_COEFFICIENT,
    MAX_POINTS,
    SECOND_COEFFICIENT,
    THIRD_COEFFICIENT,
    node_of,
)

# `panel`'s values per joint: the integral over the panel, the index of the
# first node whose torque's sign differs from the node's before (else 0), the
# torques at the two nodes about that change (else at the first and the last
# node: where a zero's search starts, without evaluating them again), then
# T's Legendre coefficients a_0..a_3, a_(n-1) on it (on a Gauss-Jacobi panel
# a_0 is the share of it that the bound may spend, `weighted_share`).
PANEL_FIELDS = 9
# Where the coefficients start in a joint's `PANEL_FIELDS`.
COEFFICIENTS = 4
# The sums over the nodes per joint: the rule's sum, the sign change, the
# torque at the node before, the two torques kept, the coefficients, then the
# weighted mean (on a Gauss-Jacobi panel).
_SUM_FIELDS = 11


def filled(like, value):
    """A tuple of `value` for each item of `like`."""
    items = ()
    for _ in range(len(like)):
        items = items + (value,)
    return items


def divides_at(divides: int, joint: int) -> bool:
    """Whether `joint`'s bit is set in `divides`."""
    return ((divides >> joint) & 1) == 1


def torque_of(values, joint: int):
    """`joint`'s torque in `torques_at`'s values."""
    torque = values[0]
    for k in range(1, len(values) // 2):
        if k == joint:
            torque = values[2 * k]
    return torque


def _started(bends):
    sums = ()
    for _ in range(len(bends)):
        sums = sums + (0.0, 0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0)
    return sums


def _node_added(sums, i: int, values, t, u, power, zero: int, divides: int, q, points: int,
                weighted: bool, bends, rb, ab, min_angle, p):  # fmt: skip
    """`sums` with node i (at t, unit node u) added for each joint: its rate
    A_k |w_k| |T_k|^p (times the substitution's q u^(q-1) `power`; on a
    Gauss-Jacobi panel q A_k |w_k| |T_k / u^q|^p, u^gamma being the rule's
    weight), its torque (divided by u^q where the joint's zero is the panel's
    end) and the torques a zero's search starts from (`PANEL_FIELDS`)."""
    # Every joint's rate first: the tables' values and the sums need not be
    # kept across the library's log and exp (callee-clobbered registers).
    rates = ()  # type: tuple
    values_divided = ()  # type: tuple
    for k in range(len(bends)):
        torque, speed = values[2 * k], values[2 * k + 1]
        angle = max(abs(bends[k] + t * (rb + 0.5 * ab * t)), min_angle)
        value = torque
        if zero != 0 and divides_at(divides, k):
            value = torque / (power * u)
        rate = angle * abs(speed) * power_of(abs(value if weighted else torque), p)
        if zero != 0:
            rate *= q if weighted else q * power
        rates = rates + (rate,)
        values_divided = values_divided + (value,)
    if weighted:
        weight, mean, zeroth = (
            JACOBI_WEIGHTS[points][i],
            JACOBI_MEAN[points][i],
            JACOBI_ZEROTH[points][i],
        )
        first, second = JACOBI_FIRST[points][i], JACOBI_SECOND[points][i]
        third, last = JACOBI_THIRD[points][i], JACOBI_LAST[points][i]
    else:
        weight = GAUSS_WEIGHTS[points][i]
        mean, zeroth = weight, weight
        first, second = FIRST_COEFFICIENT[points][i], SECOND_COEFFICIENT[points][i]
        third, last = THIRD_COEFFICIENT[points][i], LAST_COEFFICIENT[points][i]
    added = ()  # type: tuple
    for k in range(len(bends)):
        joint = sums[_SUM_FIELDS * k : _SUM_FIELDS * (k + 1)]
        total, change, before, kept_lo, kept_hi, a0, a1, a2, a3, a_last, b0 = joint
        torque, value = values[2 * k], values_divided[k]
        if i == 0:
            kept_lo = torque
        if change == 0:
            kept_hi = torque
            if (before < 0.0 and torque > 0.0) or (before > 0.0 and torque < 0.0):
                change, kept_lo = i, before
        if weighted:  # `panel` reads the weighted mean there only
            b0 = b0 + mean * value
        added = added + (
            total + weight * rates[k], change, torque, kept_lo, kept_hi,
            a0 + zeroth * value, a1 + first * value, a2 + second * value, a3 + third * value,
            a_last + last * value, b0,
        )  # fmt: skip
    return added


def panel(torques_at, step, lo, hi, zero: int, divides: int, q, points: int, weighted: bool,
          bends, rb, ab, min_angle, p):  # fmt: skip
    """Each joint's `PANEL_FIELDS` values on [lo, hi] by the `points`-point
    rule (Gauss-Jacobi's if `weighted`, else Gauss-Legendre's), substituted
    at the zero end (`zero` as `node_time`); joint k's
    integrand A_k |w_k| |T_k|^p, A_k = max(|bends[k] + rb t + ab t^2 / 2|,
    `min_angle`), (T_k, w_k) = items 2k, 2k + 1 of `torques_at(t, step)`; its
    coefficients those of T_k / u^q if its bit is set in `divides`."""
    sums = _started(bends)
    for i in range(points):
        u = node_of(points, i, weighted)
        power = whole_power(u, q - 1.0) if zero != 0 else 1.0
        t = node_time(lo, hi, u, zero, q)
        sums = _node_added(sums, i, torques_at(t, step), t, u, power, zero, divides, q, points,
                           weighted, bends, rb, ab, min_angle, p)  # fmt: skip
    values = ()  # type: tuple
    for k in range(len(bends)):
        a0 = sums[_SUM_FIELDS * k + 5]
        if weighted:
            a0 = weighted_share(a0, sums[_SUM_FIELDS * k + 10])
        values = values + (sums[_SUM_FIELDS * k] * (hi - lo), sums[_SUM_FIELDS * k + 1])
        values = values + sums[_SUM_FIELDS * k + 3 : _SUM_FIELDS * k + 5] + (a0,)
        values = values + sums[_SUM_FIELDS * k + 6 : _SUM_FIELDS * k + 10]
    return values


def totals_added(totals, values):
    """Each joint's integral so far plus its panel's."""
    added = ()
    for k in range(len(totals)):
        added = added + (totals[k] + values[PANEL_FIELDS * k],)
    return added


def scales_raised(scales, totals, values):
    """What each joint's bound is asked against: its step's integral from
    below, a quarter of its first panel's value, then what its accepted
    panels sum (every panel's part is positive). A panel that adds little to
    it may err more against its own."""
    raised = ()
    for k in range(len(scales)):
        scale = scales[k]
        if scale < 0.0:
            scale = 0.25 * values[PANEL_FIELDS * k]
        raised = raised + (max(scale, totals[k]),)
    return raised


def _joint_needs(value, change: int, coefficients, scale, n: int, budget, degree, singular,
                 substituted: bool):  # fmt: skip
    """(whether the joint's bound holds on the panel, else the points it asks
    for: as many as its zeros ask if they allow the largest rule, or twice as
    many while its highest coefficient is not yet resolved; 0 when it needs a
    cut at a zero, or halving)."""
    share = target_share(scale, value)
    required = log_rho_required(n, budget - share, degree)
    if (
        change == 0
        and required <= singular
        and (value == 0.0 or zero_free_on(required, coefficients, n, substituted))
    ):
        return True, n
    if change == 0 and n < MAX_POINTS:
        low, top = zero_free_log_rho(coefficients, n, substituted)
        own = points_for(min(singular, low), budget - share, degree)
        if own <= MAX_POINTS:
            needed = points_for(min(singular, low, top), budget - share, degree)
            resolved = needed if needed <= MAX_POINTS else 2 * n
            return False, min(MAX_POINTS, max(own, resolved, n + 1))
    return False, 0


def verdict(values, scales, n: int, budget, degree, carried, singular, divides: int):
    """(the joints whose bound fails, one bit each; the points that the
    failing ones ask for, the most any asks, or 0 if one needs a cut). On a
    substituted panel the joints whose zero it is (`divides`) take the
    substitution's power `degree` (gamma); to the others it is a change of
    variable whose Jacobian q u^(q-1) has the degree `carried`, q - 1."""
    failing, wanted = 0, n
    for k in range(len(scales)):
        holds, points = _joint_needs(
            values[PANEL_FIELDS * k], values[PANEL_FIELDS * k + 1],
            values[PANEL_FIELDS * k + COEFFICIENTS : PANEL_FIELDS * (k + 1)], scales[k], n, budget,
            degree if divides_at(divides, k) else carried, singular, divides_at(divides, k),
        )  # fmt: skip
        if not holds:
            failing = failing | (1 << k)
            wanted = 0 if points == 0 or wanted == 0 else max(wanted, points)
    return failing, wanted
