"""One Gauss-Legendre panel of the life integral and the bound on its error
(`life_integral` marches them over a step; docs/life.md, "Exact over each step").

The bound (Bernstein ellipse): with the integrand analytic and at most M
inside the ellipse E_rho about a panel (foci at its ends, rho the sum of its
semi-axes over the half-length), its Chebyshev coefficients on the panel are
at most 2 M rho^-k. The n-point rule is exact below degree 2n and, its nodes
symmetric, for every odd degree; an even T_k integrates to -2 / (k^2 - 1)
over [-1, 1] and the rule (positive weights summing to 2) gives at most 2. So
n points err by at most the sum over even k >= 2n of 2 M rho^-k (2 + 2 /
(k^2 - 1)): against the panel's integral (twice its mean), c (M / mean)
rho^-2n / (1 - rho^-2), c = 2 (1 + 1 / (4 n^2 - 1)) <= 128/63 at n >= 4.
(Ending in rho^-2n / (rho^2 - 1), as for n + 1 points, misses by rho^2.)
Two things limit rho:

- the torque's singularities (D = 0): none lies within `tau` s of a point of
  the step (`life.singularity_reach`). A plain panel's E_rho lies within its
  semi-minor axis (L/2) sinh(log rho) of the panel (the distance from the
  segment is largest on the minor axis: at u = (A cos th, B sin th), beyond
  an end by A cos th - L/2 <= B cos th as A - B = (L/2)/rho < L/2), so
  sinh(log rho) < 2 tau / L keeps them out. A substituted panel's t = t0 +
  L u^q takes E_rho about u in [0, 1] into |t - t0| <= L ((1 + x) / 2)^q,
  x = cosh(log rho) (its farthest point from u = 0), so x < 2 (tau / L)^(1/q)
  - 1 does. The ellipse reaches `_TOWARDS_SINGULARITY` of that log rho;
- the torque's complex zeros, where |T|^p branches. The Legendre coefficients
  a_k of T, exact from the panel's own values, bound |T - a_0| on E_rho: held
  within 0.9 |a_0|, T has no zero there and |T|^p <= 1.9^p |a_0|^p <= 1.9^p
  mean |T|^p (Jensen, p >= 1). The coefficients are those of T's
  interpolant through the n values: the bound is T's as far as that
  interpolant stands for T on E_rho, which the highest coefficient's share
  and the singularities' reach see to (not a proof: the tests measure the
  rest, a few 1e-12 of a step at most).

M / mean takes 1.9^p for |T|^p and 4 for the angle's and the speed's
variation over the ellipse against their mean (`_VARIATION`, assumed, not
derived). With s = log rho, n points meet the bound when 2 n s - X(s) >= B,
B = log(4 c / target) + p log 1.9 (`error_budget`) and X(s) the log of the
factors that change with rho: the tail 1 / (1 - rho^-2) and a substituted
panel's power (below), derived and solved for s in `life_ellipse`.

Each panel's bound is asked below the larger of `_OWN_TARGET` of its own
integral and `_STEP_TARGET` of the step's integral known from below
(`target_share`): over a step's N panels the bounds sum to at most 2e-10 + N
8e-12 of the step's integral, within the contract's 1e-9 up to N = 100 (a
few tens at most, but for steps of many turns).

At a torque zero t0 the panel substitutes t = t0 + L u^q: |T|^p ~ |t - t0|^p
becomes u^gamma (gamma = q (p + 1) - 1 >= 10) times a smooth factor. That
factor is T / u^q, whose coefficients the check reads. Under Gauss-Legendre
u^gamma stays in the integrand: its largest modulus on E_rho is cosh(s /
2)^(2 gamma), some 4^gamma below rho^gamma, and its mean 1 / (gamma + 1)
(`life_ellipse`; the smooth factor's mean, a_0 under Lebesgue's measure,
stands for its mean under u^gamma). The joints a chain's panel does not
divide carry the Jacobian's u^(q - 1) alike (gamma = q - 1). In u the
singularities lie nearer: a distance tau from t0 is only (tau / L)^(1/q) in u.

Where every joint's torque is divided by u^q and gamma is the tabulated 12
(p = 10/3; `quadrature.JACOBI_POWER`), the panel takes the Gauss-Jacobi rule
for the weight u^gamma instead (`rule_sizing`): the integrand is u^gamma f,
f = q A |w| |T / u^q|^p smooth, and u^gamma leaves the bound. Its bound: the
n-point rule has positive weights summing to W = 1 / (gamma + 1) and is exact
for f's Chebyshev terms of degree < 2n (on u = (1 + x) / 2), each at most
2 M rho^-k on [0, 1] with M = max |f| on E_rho; both the integral and the
rule take a term |T_k| <= 1 to at most W, so the error is at most 2 W sum_{k
>= 2n} 2 M rho^-k = 4 W M rho^-2n / (1 - 1 / rho) = 4 (1 + 1 / rho) W M
rho^-2n / (1 - rho^-2) <= 8 W M rho^-2n / (1 - rho^-2). Against the panel's
integral W mean_w f (mean_w the mean under u^gamma): 8 (M / mean_w f)
rho^-2n / (1 - rho^-2), Gauss-Legendre's with 8 for c (`_WEIGHTED_FACTOR`).
M / mean_w f takes the same 4 for the angle and
the speed and 1.9^p for |T / u^q|^p: its maximum on E_rho is at most (|a_0|
+ 0.9 s)^p when the check holds with the share s of a_0 (`weighted_share`),
its weighted mean at least |b_0|^p (Jensen under u^gamma), b_0 the weighted
mean of T / u^q (exact from the rule), and s <= (1.9 |b_0| - |a_0|) / 0.9
makes the ratio 1.9^p. The residue u^(gamma - 12) of a gamma rounded off 12
(12.000000000000002 at p = 10/3) is within 1e-12 |log u| of 1.
"""

import math

from .life_ellipse import bound_excess, log_rho_above, low_spread, spread_reach
from .quadrature import (
    JACOBI_POWER,
    MAX_POINTS,
    MIN_POINTS,
)

# Each panel's error bound against its own integral, and against the step's
# known from below (the module's allocation; the bound is far from tight).
_OWN_TARGET = 2e-10
_STEP_TARGET = 8e-12
_OWN_SHARE = math.log(_OWN_TARGET / _STEP_TARGET)
# The rule's factor c at the fewest points, and the angle's and the speed's 4.
_LEGENDRE_FACTOR = 2.0 * (1.0 + 1.0 / (4.0 * MIN_POINTS * MIN_POINTS - 1.0))
_VARIATION = 4.0
# |T - a_0| on the ellipse: a_1..a_3 take 0.8 |a_0|, a_(n-1) the last 0.1 |a_0|.
_LOW_TERMS = 0.8
_TOP_TERM = 0.1
_GROWTH = 1.0 + _LOW_TERMS + _TOP_TERM
# How far (in log rho) a panel's ellipse reaches towards the D = 0 singularities.
_TOWARDS_SINGULARITY = 0.75
# The substituted power at a torque zero: gamma = q (p + 1) - 1 at least this.
_SMOOTH_POWER = 10.0
# The Gauss-Jacobi bound's factor against Gauss-Legendre's: 8 / c.
_WEIGHTED_FACTOR = 8.0 / _LEGENDRE_FACTOR
# How far gamma may lie from the tabulated rule's power (the residue u^(gamma -
# 12) is then 1 within 1e-12 |log u|; 3 (10/3 + 1) - 1 rounds 2e-15 off 12).
_SAME_POWER = 1e-12
# `log_rho_required`'s Newton steps for a power (one takes a start a few 0.1
# off the root within a few 1e-2; a second changed no panel's points).
_SOLVE_STEPS = 1
# The largest log rho `points_for` reads (exp(700) is finite).
_FAREST = 700.0
# `longest_panel` a shade short of its closed form: `singular_log_rho` of the
# closed form's length came back an ulp or two below the log rho it was solved
# from (at p = 10/3 for almost every reach), and the verdict failed the panel
# at the largest rule it was sized for (a 0.5 s step at 10 rad/s and bend 0.5
# took 18 % more evaluations so, twice as many under load). 1e-12 moves that
# log rho by some 5e-13, thousands of ulps.
_ROUND_TRIP = 1.0 - 1e-12


def substitution_power(p):
    """q of the substitution at a torque zero: the least whole q with
    q (p + 1) - 1 >= `_SMOOTH_POWER` (q = 3, gamma = 12 for p = 10/3)."""
    return float(math.ceil((_SMOOTH_POWER + 1.0) / (p + 1.0)))


def error_budget(p):
    """B, the log of the bound's factors for exponent p over a panel's own
    target (all but those that change with rho)."""
    return math.log(_LEGENDRE_FACTOR * _VARIATION / _OWN_TARGET) + p * math.log(_GROWTH)


def target_share(scale, value):
    """What a panel whose integral is `value` may take off the budget when the
    step's integral is at least `scale`: its bound is then asked below the
    larger of `_OWN_TARGET` of its value and `_STEP_TARGET` of the scale."""
    if scale > value > 0.0:
        return max(math.log(scale / value) - _OWN_SHARE, 0.0)
    return 0.0


def rule_sizing(zero: int, divides: int, joints: int, q, gamma, budget):
    """(whether the panel takes the Gauss-Jacobi rule, its stretch, the power
    its points must resolve, its budget): a panel substituted at a zero (`zero`
    as `node_time`) takes it where every one of the `joints` divides its torque
    by u^q (`divides`, one bit each) and gamma is the tabulated power."""
    if zero == 0:
        return False, 1.0, 0.0, budget
    if divides == (1 << joints) - 1 and abs(gamma - JACOBI_POWER) <= _SAME_POWER:
        return True, q, 0.0, budget + math.log(_WEIGHTED_FACTOR)
    return False, q, gamma, budget


def weighted_share(a0, b0):
    """The share of a_0 that a Gauss-Jacobi panel's check may spend (with a_0's
    sign): |a_0|, or less where the weighted mean b_0 is smaller, so that |a_0|
    + (1.9 - 1) share <= 1.9 |b_0| (the module's bound); 0 if none is left."""
    share = min(abs(a0), (_GROWTH * abs(b0) - abs(a0)) / (_GROWTH - 1.0))
    return math.copysign(max(share, 0.0), a0)


def singular_log_rho(length, tau, stretch):
    """log rho of the ellipse about a panel of `length` s that reaches
    `_TOWARDS_SINGULARITY` of the way to the largest one free of singularities
    `tau` s from the step (the module's bound); `stretch` q for a panel
    substituted at a zero, else 1."""
    if tau == math.inf:
        return math.inf
    if stretch == 1.0:
        return _TOWARDS_SINGULARITY * math.asinh(2.0 * tau / length)
    x = 2.0 * math.exp(math.log(tau / length) / stretch) - 1.0
    return _TOWARDS_SINGULARITY * math.acosh(x) if x > 1.0 else 0.0


def points_for(log_rho, budget, gamma):
    """The points that bring the bound below its target on E_rho (rho =
    exp(`log_rho`)), gamma the substituted power (0 if none); MAX_POINTS + 1
    if more than the largest rule."""
    if log_rho <= 0.0:
        return MAX_POINTS + 1
    # Beyond, rho overflows; fewer rho asks for more points: the safe side.
    log_rho = min(log_rho, _FAREST)
    need = (budget + bound_excess(log_rho, gamma)[0]) / (2.0 * log_rho)
    if need > MAX_POINTS:
        return MAX_POINTS + 1
    return max(MIN_POINTS, math.ceil(need))


def log_rho_required(points, budget, gamma):
    """The log rho with which `points` points meet the bound (`points_for`'s
    inverse), never below the root but by its rounding (`life_ellipse`)."""
    return log_rho_above(points, budget, gamma, _SOLVE_STEPS)


def longest_panel(tau, budget, gamma, stretch):
    """The longest panel the largest rule covers as far as the singularities
    go (`singular_log_rho`'s inverse at the largest rule's log rho)."""
    if tau == math.inf:
        return math.inf
    per_point = log_rho_above(MAX_POINTS, budget, gamma, 0)
    if stretch == 1.0:
        return _ROUND_TRIP * 2.0 * tau / math.sinh(per_point / _TOWARDS_SINGULARITY)
    x = 0.5 * (1.0 + math.cosh(per_point / _TOWARDS_SINGULARITY))
    return _ROUND_TRIP * tau / whole_power(x, stretch)


def zero_free_on(log_rho, coefficients, points, substituted: bool) -> bool:
    """Whether T, with these Legendre coefficients (a_0..a_3, a_(n-1)) on the
    panel, keeps |T - a_0| <= 0.9 |a_0| on E_rho (rho = exp(`log_rho`)): there
    |P_k| is at most P_k(x) <= rho^k, x = cosh(log rho); a_1..a_3 take 0.8
    |a_0|, a_(n-1) the last 0.1 |a_0|. A substituted panel skips a_(n-1):
    dividing out u^q magnifies the rounding of T next to its zero, which the
    highest coefficient feels first, while a_1..a_3 see a zero inside E_rho
    all the same. A Gauss-Jacobi panel's a_0 is its share (`weighted_share`):
    none left, the check fails."""
    a0, a1, a2, a3, a_last = coefficients
    size = abs(a0)
    if size == 0.0:
        return False
    rho = math.exp(log_rho)
    if low_spread(0.5 * (rho + 1.0 / rho), abs(a1), abs(a2), abs(a3)) > _LOW_TERMS * size:
        return False
    return substituted or abs(a_last) * whole_power(rho, points - 1.0) <= _TOP_TERM * size


def zero_free_log_rho(coefficients, points, substituted: bool):
    """(the largest log rho on which a_1..a_3 keep to `zero_free_on`'s share,
    the largest on which a_(n-1) does); 0.0 where there is none. The first is
    T's own (its zeros'), the second grows with the points (how well they
    resolve T). The first's cosh is the root of a cubic (`spread_reach`)."""
    a0, a1, a2, a3, a_last = coefficients
    size = abs(a0)
    c1, c2, c3 = abs(a1), abs(a2), abs(a3)
    if c1 + c2 + c3 >= _LOW_TERMS * size:
        return 0.0, 0.0
    low = math.inf
    if c1 != 0.0 or c2 != 0.0 or c3 != 0.0:
        low = math.acosh(spread_reach(c1, c2, c3, _LOW_TERMS * size))
    if substituted or a_last == 0.0:
        return low, math.inf
    if _TOP_TERM * size <= abs(a_last):
        return low, 0.0
    return low, math.log(_TOP_TERM * size / abs(a_last)) / (points - 1.0)


def may_vanish(coefficients):
    """Whether T's interpolant may reach zero on the panel (|P_k| <= 1 there)."""
    a0, a1, a2, a3, a_last = coefficients
    return abs(a1) + abs(a2) + abs(a3) + abs(a_last) >= abs(a0)


def power_of(x, p):
    """x^p for x >= 0 as exp(p log x): the library's pow costs half as much
    again, and the rounding of p log x (|p log x| < 100 at the loads and
    exponents a joint sees) is a few 1e-15 of x^p, far inside the bound."""
    if x == 0.0:
        return 0.0
    return math.exp(p * math.log(x))


def whole_power(u, k):
    """u^k for whole k >= 0 by products: the substitution's powers without pow."""
    power = 1.0
    for _ in range(int(k)):
        power *= u
    return power


def node_time(lo, hi, u, zero, q):
    """The time of unit node u on [lo, hi]: plain, or substituted at the zero
    end (`zero` 1 at lo, -1 at hi, else 0)."""
    if zero > 0:
        return lo + (hi - lo) * whole_power(u, q)
    if zero < 0:
        return hi - (hi - lo) * whole_power(u, q)
    return lo + (hi - lo) * u
