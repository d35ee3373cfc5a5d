"""The points a panel of the life integral is likely to ask for, foreseen
before it is taken from a plain panel about it that failed (`life_integral`;
docs/life.md, "Exact over each step"): a guess that saves taking the panel
twice, or halving it after it was taken. The verdict (`life_nodes.verdict`)
judges every panel all the same.

The failed panel's values hold each joint's cubic part a_0..a_3 of T in
Legendre polynomials of its x in [-1, 1]. A plain panel inside it is an
interval of x; a panel substituted at a zero t0 inside it, t = t0 +- L u^q,
is x = x0 + s u^q, u in [0, 1] (q = 1 for the plain one). Either way the
panel's own cubic part is that of the failed panel's cubic composed with the
map: the cubic's Taylor terms about x0 make it sum_i c_i s^i u^(q i), whose
Legendre coefficients a_0..a_3 follow exactly from those of u^(q i), a
table of rationals (`_MOMENTS`). A joint whose zero is t0 is divided by u^q
on the panel: its cubic, divided by x - x0 (the zero's factor, up to the
cubic's remainder there, c_0), stands for it: the same terms from c_1 on.
The last step's last plain panel foresees the step's first panel alike:
that panel's x runs on beyond 1 into the step, an interval of the same x.
`life_nodes.verdict` reads the same coefficients with `life_panel`'s bound;
a joint whose cubic keeps to it on the ellipse the panel's points need asks
for no more, which spares solving for its reach.
"""

import math
from fractions import Fraction

from .life_nodes import COEFFICIENTS, PANEL_FIELDS, divides_at
from .life_panel import log_rho_required, points_for, zero_free_log_rho, zero_free_on
from .quadrature import MAX_POINTS

# The share of its quotient's zeros' reach (log rho) that a divided joint is
# foreseen with: dividing by x - x0 weighs the terms beyond the cubic, which
# the foresight leaves out, by their slope (up to k^2 |a_k| for P_k), so the
# quotient foresees T / u^q less well than the cubic T; the verdict found its
# reach some 10 % shorter at 1000 rad/s. Evaluations a step of a joint at 300
# to 1000 rad/s, loads of both signs: the least at 0.8 (1000 rad/s: 56.4 at
# 1, 55.7 at 0.9, 54.0 at 0.8, 54.9 at 0.7), none dearer than at 1.
_DIVIDED_REACH = 0.8


def _moment(degree: int, k: int) -> float:
    """(2k + 1) int_0^1 u^degree P_k(2u - 1) du: degree!^2 / ((degree - k)!
    (degree + k + 1)!) times 2k + 1, 0 below k (P_k is orthogonal to lower
    degrees), exact before it is rounded."""
    if degree < k:
        return 0.0
    exact = Fraction(
        math.factorial(degree) ** 2,
        math.factorial(degree - k) * math.factorial(degree + k + 1),
    )
    return float((2 * k + 1) * exact)


# Row q, item 4k + i: the Legendre coefficient a_k on u in [0, 1] of u^(q i),
# for every whole q the substitution takes (`life_panel.substitution_power`
# is at most 11 for p > 0).
_MOMENTS = tuple(tuple(_moment(q * i, k) for k in range(4) for i in range(4)) for q in range(12))


def _composed(cubic, origin, stretch, power, divided: bool):
    """The Legendre coefficients a_0..a_3 on u in [0, 1] of the cubic with
    coefficients `cubic` (a_0..a_3 in x) taken at x = origin + stretch
    u^power (`power` whole); if `divided`, of the cubic over u^power."""
    a0, a1, a2, a3 = cubic
    m0, m1, m2, m3 = a0 - 0.5 * a2, a1 - 1.5 * a3, 1.5 * a2, 2.5 * a3
    # The cubic in s = u^power: its Taylor terms about origin.
    c0 = m0 + origin * (m1 + origin * (m2 + origin * m3))
    c1 = stretch * (m1 + origin * (2.0 * m2 + 3.0 * origin * m3))
    c2 = stretch * stretch * (m2 + 3.0 * origin * m3)
    c3 = stretch * stretch * stretch * m3
    if divided:
        # Over x - origin = stretch s (c0, the cubic at origin, is the
        # remainder: its misplacement of the zero), times stretch: over s.
        c0, c1, c2, c3 = c1, c2, c3, 0.0
    q = int(power)
    return (
        c0 * _MOMENTS[q][0] + c1 * _MOMENTS[q][1] + c2 * _MOMENTS[q][2] + c3 * _MOMENTS[q][3],
        c0 * _MOMENTS[q][4] + c1 * _MOMENTS[q][5] + c2 * _MOMENTS[q][6] + c3 * _MOMENTS[q][7],
        c0 * _MOMENTS[q][8] + c1 * _MOMENTS[q][9] + c2 * _MOMENTS[q][10] + c3 * _MOMENTS[q][11],
        c0 * _MOMENTS[q][12] + c1 * _MOMENTS[q][13] + c2 * _MOMENTS[q][14] + c3 * _MOMENTS[q][15],
    )


def cubics_of(values):
    """Each joint's a_0..a_3 in a panel's values (`life_nodes.panel`): what a
    plain panel about others foresees them from."""
    cubics = ()  # type: tuple
    for k in range(len(values) // PANEL_FIELDS):
        cubics = (
            cubics + values[PANEL_FIELDS * k + COEFFICIENTS : PANEL_FIELDS * k + COEFFICIENTS + 4]
        )
    return cubics


def cubics_foreseen(guide, guide_lo, guide_hi, lo, hi, zero: int, q, divides: int):
    """Each joint's a_0..a_3 on the panel [lo, hi] (substituted at its `zero`
    end as `life_panel.node_time`; its torque over u^q where its bit is set
    in `divides`, 0 on a plain panel), foreseen from the plain panel
    [guide_lo, guide_hi] whose cubics (`cubics_of`) are `guide`: about the
    panel, or before it (the last step's, `life_integral.step_integrals`)."""
    at = hi if zero < 0 else lo
    origin = (2.0 * at - guide_lo - guide_hi) / (guide_hi - guide_lo)
    stretch = 2.0 * (hi - lo) / (guide_hi - guide_lo)
    if zero < 0:
        stretch = -stretch
    power = q if zero != 0 else 1.0
    cubics = ()  # type: tuple
    for k in range(len(guide) // 4):
        cubics = cubics + _composed(guide[4 * k : 4 * k + 4], origin, stretch, power,
                                    divides_at(divides, k))  # fmt: skip
    return cubics


def points_foreseen(guide, guide_lo, guide_hi, lo, hi, zero: int, q, divides: int, points: int,
                    singular, budget, degree, carried):  # fmt: skip
    """The points the panel [lo, hi] inside the plain panel [guide_lo,
    guide_hi] that failed (its cubics `guide`), or after the last step's last
    plain panel, is likely to ask for
    (`cubics_foreseen`), at least its `points` (which `singular`, the
    panel's singularities' log rho, allows): the most that any joint's zeros
    ask for, by `points_for` with the power `verdict` gives the joint
    (`degree` where its bit is set in `divides`, else `carried`); MAX_POINTS
    + 1 if they allow no rule (a cut)."""
    cubics = cubics_foreseen(guide, guide_lo, guide_hi, lo, hi, zero, q, divides)
    wanted = points
    # The ellipse `points` need, solved once for joints of the same power
    # (on a plain panel all are 0).
    required, solved = 0.0, -1.0
    for k in range(len(cubics) // 4):
        divided = divides_at(divides, k)
        power = degree if divided else carried
        reach = _DIVIDED_REACH if divided else 1.0
        cubic = cubics[4 * k : 4 * k + 4] + (0.0,)
        if power != solved:
            required, solved = log_rho_required(points, budget, power), power
        # Zero-free on the ellipse `points` need, the joint asks no more (its
        # cubic has no a_(n-1) to check).
        if not zero_free_on(required / reach, cubic, points, True):
            low = reach * zero_free_log_rho(cubic, MAX_POINTS, False)[0]
            wanted = max(wanted, points_for(min(singular, low), budget, power))
    return wanted
