"""The factors of a life panel's error bound that change with the ellipse
E_rho about it, the log rho that given points need (`life_panel`'s bound:
with s = log rho, n points meet it when G(s) = 2 n s - X(s) >= B), and the
cosh(log rho) at which a torque's Legendre coefficients reach their share
(`spread_reach`).

X(s) is the log of those factors:

- the tail 1 / (1 - rho^-2) of the rule's geometric sum. log(1 / (1 - x))
  <= x / (1 - x) bounds its log by 1 / (rho^2 - 1) = 1 / (e^2s - 1), and
  e^2s - 1 >= 2s (1 + s + 2s^2 / 3) (its cubic Taylor part) by 1 / (2s (1 +
  s + 2s^2 / 3)): convex, decreasing, without exp, and within 0.05 of the
  exact log from s = 1 on;
- on a panel substituted at a torque zero under Gauss-Legendre, u^gamma's
  largest modulus on E_rho about u in [0, 1] over its mean 1 / (gamma + 1).
  There |u| = |1 + x| / 2, x in the ellipse with foci -1 and 1, and a
  point's distance from a focus is at most the semi-major axis cosh s plus
  the focal distance 1, reached at the far vertex: max |u^gamma| = ((1 +
  cosh s) / 2)^gamma = cosh(s / 2)^(2 gamma) = ((1 + rho)^2 / (4 rho))^gamma,
  some 4^gamma below the rho^gamma it was bounded by. Its log, 2 gamma log
  cosh(s / 2), is convex with slope gamma tanh(s / 2) < gamma.

So G is concave and increasing with G' > 2n - gamma. For given s the points
follow in closed form (`life_panel.points_for`). For given points the root
of G(s) = B has none: `log_rho_above` starts on its left (G(s0) <= B from
log cosh(s / 2) >= s / 2 - log 2 and X's tail >= 0), where Newton's steps
stay (a concave function lies below its tangents), then takes one step with
the least slope 2n - gamma, which cannot fall short of the root: the safe
side, asking for more rho.
"""

import math

_LOG_TWO = math.log(2.0)
# The halvings that bring a start at or below 0 to the left (the least budget,
# -1420 at the largest share, is met near s = 2e-4, 12 halvings from 1).
_HALVINGS = 40
# `spread_reach`'s Newton steps at most: they stop on the root, which far above
# it each step divides x by at least 3/2 (a cubic's), so this many reach it
# from a start 1e6 times too high (one with |a_3| 1e-36 of |a_0|).
_SPREAD_STEPS = 40


def bound_excess(log_rho, gamma):
    """(X(s), X'(s)) at s = `log_rho`: the module's X, the tail's bound and,
    for a power gamma (0 if none), log(max |u^gamma| (gamma + 1)), with
    cosh(s / 2)^2 = (1 + rho)^2 / (4 rho)."""
    return _excess(log_rho, gamma, math.log(gamma + 1.0) if gamma != 0.0 else 0.0)


def _excess(log_rho, gamma, log_mean):
    """`bound_excess` with log(gamma + 1) given (a solve's steps share it)."""
    below = 2.0 * log_rho * (1.0 + log_rho * (1.0 + log_rho / 1.5))
    excess = 1.0 / below
    slope = -(2.0 + 4.0 * log_rho * (1.0 + log_rho)) / (below * below)
    if gamma != 0.0:
        rho = math.exp(log_rho)
        excess += gamma * (2.0 * math.log(1.0 + rho) - log_rho - 2.0 * _LOG_TWO)
        excess += log_mean
        slope += gamma * (1.0 - 2.0 / (1.0 + rho))
    return excess, slope


def log_rho_above(points, budget, gamma, steps: int):
    """A log rho at or above the root of G(s) = B (the module's solve): from
    a start on the left, `steps` Newton steps (for a power gamma), then one
    with G's least slope."""
    least_slope = 2.0 * points - gamma
    if least_slope <= 0.0:
        return math.inf
    s = budget / least_slope
    if gamma == 0.0 and s > 0.0:  # on the left, X' < 0: the last step alone
        return s + bound_excess(s, 0.0)[0] / least_slope
    log_mean = math.log(gamma + 1.0) if gamma != 0.0 else 0.0
    if gamma != 0.0:
        # G(s) <= (2n - gamma) s + 2 gamma log 2 - log(gamma + 1).
        s += (log_mean - 2.0 * gamma * _LOG_TWO) / least_slope
    if not s > 0.0:
        s = 1.0
    excess, slope = _excess(s, gamma, log_mean)
    for _ in range(_HALVINGS):
        if 2.0 * points * s - excess <= budget:
            break
        s *= 0.5
        excess, slope = _excess(s, gamma, log_mean)
    if 2.0 * points * s - excess > budget:  # a budget below any rho's: s is right of the root
        return s
    if gamma != 0.0:  # else the start is the root's to a few 1e-3
        for _ in range(steps):
            s += (budget - 2.0 * points * s + excess) / (2.0 * points - slope)
            excess, slope = _excess(s, gamma, log_mean)
    return s + max(budget - 2.0 * points * s + excess, 0.0) / least_slope


def low_spread(x, c1, c2, c3):
    """|a_1| P_1(x) + |a_2| P_2(x) + |a_3| P_3(x), given the |a_k|: at x =
    cosh(log rho), the most |P_k| reaches on E_rho."""
    return c1 * x + c2 * (1.5 * x * x - 0.5) + c3 * (2.5 * x * x - 1.5) * x


def _spread_bound(c1, c2, c3, limit):
    """An x >= 1 at or above the root of `low_spread` = `limit`: P_3(x) >=
    P_2(x) there, so the spread is at least c1 x + (c2 + c3) P_2(x), whose
    root, in the form that does not cancel and in units of the limit (each
    share below 1: no square overflows), lies at or above the cubic's."""
    linear, high = c1 / limit, (c2 + c3) / limit
    free = 1.0 + 0.5 * high
    below = linear + math.sqrt(linear * linear + 6.0 * high * free)
    if below == 0.0:  # every share under the smallest double: the root is beyond reach
        return math.inf
    return 2.0 * free / below


def spread_reach(c1, c2, c3, limit):
    """The x >= 1 where `low_spread` reaches `limit` (below it at x = 1, some
    |a_k| not 0), by Newton's method from `_spread_bound`: the cubic is convex
    and increasing for x >= 1, so the steps fall towards the root and stop
    where they no longer fall (on the root, to its rounding), or after
    `_SPREAD_STEPS`: still above the root where a_3 alone is under some 1e-36
    of the limit (a root past log rho 28, where every rule takes its fewest
    points). Above the root is the side of fewer points: the reach only
    sizes a failing panel's retake, the bound judges it (`zero_free_on`)."""
    x = _spread_bound(c1, c2, c3, limit)
    for _ in range(_SPREAD_STEPS):
        slope = c1 + 3.0 * c2 * x + c3 * (7.5 * x * x - 1.5)
        lower = x - (low_spread(x, c1, c2, c3) - limit) / slope
        if not lower < x:
            break
        x = lower
    return x
