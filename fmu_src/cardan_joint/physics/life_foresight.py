"""The points a panel of the life integral is likely to ask for, foreseen
before it is taken from a plain panel about it that failed (`life_integral`;
docs/life.md, "Exact over each step"): a guess that saves taking the panel
twice, or halving it after it was taken. The verdict (`life_nodes.verdict`)
judges every panel all the same.

The failed panel's values hold each joint's cubic part a_0..a_3 of T in
Legendre polynomials of its x in [-1, 1]. A plain panel inside it is an
interval of x; a panel substituted at a zero t0 inside it, t = t0 +- L u^q,
is x = x0 + s u^q, u in [0, 1]. Either way the panel's own cubic part is
that of the failed panel's cubic composed with the map: a polynomial of
degree 3 q in u, whose coefficients a_0..a_3 the n-point Gauss-Legendre
rule gives exactly (the products have degree 3 q + 3 <= 2 n - 1). A joint
whose zero is t0 is divided by u^q on the panel: its cubic, divided by x -
x0 (the zero's factor, up to the cubic's remainder there), stands for it.
`life_nodes.verdict` reads the same coefficients with `life_panel`'s bound.
"""

from .life_nodes import COEFFICIENTS, PANEL_FIELDS, divides_at
from .life_panel import points_for, whole_power, zero_free_log_rho
from .quadrature import (
    FIRST_COEFFICIENT,
    GAUSS_NODES,
    GAUSS_WEIGHTS,
    MAX_POINTS,
    SECOND_COEFFICIENT,
    THIRD_COEFFICIENT,
)


def _composed(cubic, origin, stretch, power, divided: bool):
    """The Legendre coefficients a_0..a_3 on u in [0, 1] of the cubic with
    coefficients `cubic` (a_0..a_3 in x) taken at x = origin + stretch
    u^power (`power` whole); if `divided`, of the cubic over u^power."""
    a0, a1, a2, a3 = cubic
    m0, m1, m2, m3 = a0 - 0.5 * a2, a1 - 1.5 * a3, 1.5 * a2, 2.5 * a3
    if divided:
        # The cubic over x - origin (synthetic division: its remainder, the
        # cubic at origin, is left out), times stretch: over u^power.
        quotient = m2 + origin * m3
        m0, m1, m2, m3 = stretch * (m1 + origin * quotient), stretch * quotient, stretch * m3, 0.0
    # The least n with 2 n - 1 >= 3 power + 3.
    points = int(1.5 * power + 2.5)
    b0, b1, b2, b3 = 0.0, 0.0, 0.0, 0.0
    for i in range(points):
        x = origin + stretch * whole_power(GAUSS_NODES[points][i], power)
        value = m0 + x * (m1 + x * (m2 + x * m3))
        b0 += GAUSS_WEIGHTS[points][i] * value
        b1 += FIRST_COEFFICIENT[points][i] * value
        b2 += SECOND_COEFFICIENT[points][i] * value
        b3 += THIRD_COEFFICIENT[points][i] * value
    return b0, b1, b2, b3


def cubics_foreseen(guide, guide_lo, guide_hi, lo, hi, zero: int, q, divides: int):
    """Each joint's a_0..a_3 on the panel [lo, hi] (substituted at its `zero`
    end as `life_panel.node_time`; its torque over u^q where its bit is set
    in `divides`, 0 on a plain panel), foreseen from the plain panel
    [guide_lo, guide_hi] about it whose values are `guide`."""
    at = hi if zero < 0 else lo
    origin = (2.0 * at - guide_lo - guide_hi) / (guide_hi - guide_lo)
    stretch = 2.0 * (hi - lo) / (guide_hi - guide_lo)
    if zero < 0:
        stretch = -stretch
    power = q if zero != 0 else 1.0
    cubics = ()  # type: tuple
    for k in range(len(guide) // PANEL_FIELDS):
        cubic = guide[PANEL_FIELDS * k + COEFFICIENTS : PANEL_FIELDS * k + COEFFICIENTS + 4]
        cubics = cubics + _composed(cubic, origin, stretch, power, divides_at(divides, k))
    return cubics


def points_foreseen(guide, guide_lo, guide_hi, lo, hi, zero: int, q, divides: int, singular,
                    budget, degree, carried):  # fmt: skip
    """The points the panel [lo, hi] inside the plain panel [guide_lo,
    guide_hi] that failed (its values `guide`) is likely to ask for
    (`cubics_foreseen`): the most that any joint's zeros ask for, by
    `points_for` with the power `verdict` gives the joint (`degree` where
    its bit is set in `divides`, else `carried`); MAX_POINTS + 1 if they
    allow no rule (a cut). `singular` and `budget` are the panel's."""
    cubics = cubics_foreseen(guide, guide_lo, guide_hi, lo, hi, zero, q, divides)
    wanted = 0
    for k in range(len(cubics) // 4):
        low = zero_free_log_rho(cubics[4 * k : 4 * k + 4] + (0.0,), MAX_POINTS, False)[0]
        power = degree if divides_at(divides, k) else carried
        wanted = max(wanted, points_for(min(singular, low), budget, power))
    return wanted
