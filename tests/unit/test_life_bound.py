"""The life panels' error bound made exact where it was loose (`life_panel`'s
and `life_ellipse`'s docstrings), each factor against an independent
derivation: the largest |u|^gamma on the Bernstein ellipse by a brute-force
maximum over its boundary (mpmath), the tail's sum by mpmath, Gauss-Legendre's
error on a function with a known pole against the bound, the solve for log rho
against mpmath's bisection of the same equation, the torque's zeros' reach
against mpmath's root of its cubic, and the per-panel targets against the
step's 1e-9."""

import math

import mpmath
import pytest

from cardan_joint.physics import life_ellipse, life_panel
from cardan_joint.physics.life_ellipse import bound_excess
from cardan_joint.physics.life_panel import (
    error_budget,
    log_rho_required,
    points_for,
    target_share,
    zero_free_log_rho,
)
from cardan_joint.physics.quadrature import MAX_POINTS, MIN_POINTS, gauss_rule

_P = 10.0 / 3.0
_GAMMA = 3.0 * (_P + 1.0) - 1.0  # 12.000000000000002, as the march computes it
_LOG_RHOS = (0.05, 0.3, 0.65, 1.0, 1.7, 3.0, 6.0)


def _largest_u_on_ellipse(log_rho, samples=4001):
    """max |u| over E_rho's boundary, u = (1 + x) / 2, by brute force (the
    maximum modulus principle puts it on the boundary); the angles avoid the
    vertices."""
    rho = mpmath.e ** mpmath.mpf(log_rho)
    largest = mpmath.mpf(0)
    for k in range(samples):
        theta = 2 * mpmath.pi * (k + 0.37) / samples
        x = (rho * mpmath.expj(theta) + mpmath.expj(-theta) / rho) / 2
        largest = max(largest, abs((1 + x) / 2))
    return largest


@pytest.mark.parametrize("gamma", [2.0, _GAMMA, 10.5])
def test_the_powers_factor_is_its_largest_modulus_on_the_ellipse_over_its_mean(gamma):
    with mpmath.workdps(30):
        for s in _LOG_RHOS:
            power = bound_excess(s, gamma)[0] - bound_excess(s, 0.0)[0]
            largest = _largest_u_on_ellipse(s)
            brute = float(gamma * mpmath.log(largest) + mpmath.log(gamma + 1))
            # The bound is the maximum: at least every sampled point's, and
            # within the samples' spacing of them.
            assert brute <= power + 1e-12
            assert power - brute <= 1e-5 * gamma
            # rho^gamma, the bound before, is some 4^gamma above it for large rho.
            if s >= 3.0:
                assert gamma * s + math.log(gamma + 1.0) - power > gamma * math.log(3.6)


def test_the_tails_factor_covers_the_rules_geometric_sum():
    # log(1 / (1 - rho^-2)) <= its rational bound, close to it from log rho 1
    # on; X' is X's derivative (Newton's steps read it; central differences).
    with mpmath.workdps(30):
        for s in (*_LOG_RHOS, 12.0, 40.0):
            tail = bound_excess(s, 0.0)[0]
            exact = float(-mpmath.log(1 - mpmath.e ** (-2 * mpmath.mpf(s))))
            assert exact <= tail
            if s >= 1.0:
                assert tail - exact < 0.05
            for gamma in (0.0, 2.0, _GAMMA):
                step = 1e-5 * s
                ahead, behind = bound_excess(s + step, gamma)[0], bound_excess(s - step, gamma)[0]
                derivative = (ahead - behind) / (2.0 * step)
                assert math.isclose(
                    bound_excess(s, gamma)[1], derivative, rel_tol=1e-5, abs_tol=1e-9
                )


def _legendre_error_and_bound(points, pole_rho, log_rho):
    """(the relative error of the `points`-point rule on [0, 1] for 1 / (z0 -
    x), x = 2u - 1, whose pole z0 lies on E_pole_rho; the module's bound for
    it on E_rho, rho < pole_rho: c (M / mean) rho^-2n / (1 - rho^-2))."""
    z0 = (pole_rho + 1.0 / pole_rho) / 2.0
    nodes, weights = gauss_rule(points)
    rule = math.fsum(w / (z0 - (2.0 * u - 1.0)) for u, w in zip(nodes, weights))
    with mpmath.workdps(40):
        exact = float(mpmath.log((z0 + 1) / (z0 - 1)) / 2)  # the mean over [0, 1]
    rho = math.exp(log_rho)
    largest = 1.0 / (z0 - math.cosh(log_rho))  # at the vertex nearest the pole
    bound = life_panel._LEGENDRE_FACTOR * largest / exact * rho ** (-2 * points) / (1.0 - rho**-2)
    return abs(rule - exact) / exact, bound


@pytest.mark.parametrize("pole_rho", [1.5, 3.0, 10.0, 50.0])
def test_gauss_legendre_errs_within_the_bound_for_a_pole_at_any_distance(pole_rho):
    for points in range(MIN_POINTS, 11):
        for k in range(1, 40):
            log_rho = math.log(pole_rho) * k / 40.0
            error, bound = _legendre_error_and_bound(points, pole_rho, log_rho)
            assert error <= bound + 2e-15, (points, pole_rho, log_rho)  # + its rounding
    # The bound as it stood, rho^-2n / (rho^2 - 1), is that of n + 1 points: a
    # pole far off breaks it by up to rho^2.
    error, bound = _legendre_error_and_bound(4, 50.0, math.log(49.0))
    assert error > bound * (1.0 - 49.0**-2) / (49.0**2 - 1.0) * 10.0


def test_the_rules_error_on_each_chebyshev_term_is_the_bounds():
    # |I(T_k) - Q_n(T_k)| <= 2 + 2 / (k^2 - 1) on [-1, 1], 0 for odd k and below
    # 2n (the factor c = 2 (1 + 1 / (4 n^2 - 1)) <= 128/63).
    assert life_panel._LEGENDRE_FACTOR == 128.0 / 63.0
    for points in (MIN_POINTS, 7, 12):
        nodes, weights = gauss_rule(points)
        for k in range(0, 6 * points):
            rule = 2.0 * math.fsum(
                w * math.cos(k * math.acos(2.0 * u - 1.0)) for u, w in zip(nodes, weights)
            )
            exact = 0.0 if k % 2 else -2.0 / (k * k - 1.0)
            if k < 2 * points or k % 2:
                assert abs(rule - exact) < 1e-13
            else:
                assert abs(rule - exact) <= 2.0 + 2.0 / (k * k - 1.0) + 1e-13


def _root(points, budget, gamma):
    """The root of G(s) = 2 n s - X(s) = B by mpmath's bisection, X the
    module's (the tail's rational bound and the power's log cosh, from their
    formulas, not the module's code)."""
    with mpmath.workdps(40):

        def below(s):
            tail = 1 / (2 * s * (1 + s + 2 * s * s / 3))
            power = 0
            if gamma:
                power = 2 * gamma * mpmath.log(mpmath.cosh(s / 2)) + mpmath.log(gamma + 1)
            return 2 * points * s - tail - power < budget

        lo, hi = mpmath.mpf("1e-30"), mpmath.mpf(200)
        for _ in range(200):
            mid = (lo + hi) / 2
            lo, hi = (mid, hi) if below(mid) else (lo, mid)
        return float(hi)


@pytest.mark.parametrize("gamma", [0.0, 2.0, _GAMMA])
def test_log_rho_required_ends_on_the_safe_side_of_the_root(gamma):
    budget = error_budget(_P)
    for points in range(MIN_POINTS, MAX_POINTS + 1):
        if 2.0 * points <= gamma:
            # The power alone outgrows what the points resolve: no rho will do.
            assert log_rho_required(points, budget, gamma) == math.inf
            continue
        for share in (-2.0, 0.0, 3.0, 10.0, 25.0, 40.0, 1e4):
            root = _root(points, budget - share, gamma)
            got = log_rho_required(points, budget - share, gamma)
            assert got >= root * (1.0 - 1e-14), (points, share)
            # Close above it for the shares a panel of some weight takes (1/500
            # of the step's integral or more), where the least slope 2n - gamma
            # does not magnify the last step.
            if share <= 3.0 and 2.0 * points - gamma >= 4.0:
                assert got <= root * 1.05, (points, share, got, root)
            # Those points meet the bound there (but by its rounding).
            assert points_for(got * (1.0 + 1e-12), budget - share, gamma) <= points


def test_points_for_asks_for_the_fewest_points_that_meet_the_bound():
    budget = error_budget(_P)
    for gamma in (0.0, 2.0, _GAMMA):
        for s in (*_LOG_RHOS, 50.0):
            n = points_for(s, budget, gamma)
            if n > MAX_POINTS:
                assert 2 * MAX_POINTS * s - bound_excess(s, gamma)[0] < budget
                continue
            assert 2 * n * s - bound_excess(s, gamma)[0] >= budget
            if n > MIN_POINTS:
                assert 2 * (n - 1) * s - bound_excess(s, gamma)[0] < budget
    # No singularity, no zero: u^12 itself asks for 7 points (degree 13 exact),
    # not the 6 that rho^gamma's gamma / 2 gave.
    assert points_for(math.inf, budget, _GAMMA) == 7
    assert points_for(math.inf, budget, 0.0) == MIN_POINTS


def test_each_panels_target_keeps_the_step_within_1e_9():
    # Asked below the larger of 2e-10 of its own integral and 8e-12 of the
    # step's so far, 100 panels of any sizes sum to at most 1e-9 of the step.
    for scale, value in ((1.0, 1.0), (1.0, 0.2), (1.0, 1e-3), (1.0, 1e-30), (2.0, 3.0)):
        target = 2e-10 * math.exp(target_share(scale, value))
        assert math.isclose(target * value, max(2e-10 * value, 8e-12 * scale), rel_tol=1e-12)
    assert target_share(1.0, 0.0) == 0.0
    sizes = [0.5**k for k in range(100)]
    total = sum(sizes)
    bounds = sum(max(2e-10 * v, 8e-12 * total) for v in sizes)
    assert bounds <= 1e-9 * total


@pytest.mark.parametrize("gamma", [0.0, _GAMMA])
def test_a_budget_below_any_rhos_gives_a_log_rho_above_its_root(gamma):
    # A panel whose share is far beyond its budget (a sliver of the step): the
    # start is halved onto the left; past the halvings (a budget no share
    # reaches) it is already right.
    for budget in (-50.0, -1420.0, -1e5, -1e13):
        got = log_rho_required(10, budget, gamma)
        assert got > 0.0
        assert got >= _root(10, budget, gamma) * (1.0 - 1e-14)


def _spread_root(c1, c2, c3, limit):
    """The x >= 1 where |a_1| P_1(x) + |a_2| P_2(x) + |a_3| P_3(x) = limit, by
    mpmath's bisection (the spread at x = 1 below the limit)."""
    with mpmath.workdps(40):
        c1, c2, c3, limit = map(mpmath.mpf, (c1, c2, c3, limit))

        def excess(x):
            return c1 * x + c2 * (1.5 * x * x - 0.5) + c3 * (2.5 * x**3 - 1.5 * x) - limit

        low, high = mpmath.mpf(1), mpmath.mpf(2)
        while excess(high) < 0:
            low, high = high, 2 * high
        for _ in range(200):
            middle = (low + high) / 2
            low, high = (middle, high) if excess(middle) < 0 else (low, middle)
        return low


# |a_1|, |a_2|, |a_3| over |a_0|: the benchmarks' panels (a_1 leads), each alone,
# a_3 leading (8 Newton steps from x = 1 ended 113 times above the root), near
# the 0.8 that leaves no ellipse, and spreads down to 1e-12.
_SPREADS = (
    (0.32, 1.1e-3, 2e-4), (0.0942, 6.2e-3, 1e-4), (0.0117, 5.7e-3, 3e-5), (0.64, 0.018, 4e-4),
    (1e-3, 1e-5, 1e-9), (1e-4, 0.0, 0.0), (0.0, 1e-4, 0.0), (0.0, 0.0, 1e-6), (0.0, 0.3, 0.4),
    (0.2, 0.3, 0.29), (1e-12, 1e-12, 1e-12), (0.0, 1e-3, 1e-12),
)  # fmt: skip


@pytest.mark.parametrize("size", [1.7, 1e-200, 1e200])
@pytest.mark.parametrize("spread", _SPREADS)
def test_the_torques_zeros_reach_is_its_cubics_root(spread, size):
    # Newton's steps start above the root (life_ellipse._spread_bound) and end
    # on it: log rho = acosh(x) within the rounding of x (magnified by acosh's
    # slope 1 / sinh near x = 1), at any scale of the torque.
    c1, c2, c3 = (size * c for c in spread)
    limit = 0.8 * size
    root = _spread_root(c1, c2, c3, limit)
    assert life_ellipse._spread_bound(c1, c2, c3, limit) >= float(root) * (1.0 - 1e-15)
    low = zero_free_log_rho((-size, c1, -c2, c3, 0.0), 6, True)[0]
    with mpmath.workdps(40):
        exact = mpmath.acosh(root)
        assert abs(low - exact) <= 1e-14 * exact + 4e-16 / mpmath.sinh(exact), (low, exact)


def test_the_zeros_reach_takes_a_few_newton_steps_for_the_benchmarks_panels(monkeypatch):
    # They stop where x no longer falls: 6 spread evaluations at most, not 40.
    calls = []
    spread = life_ellipse.low_spread
    monkeypatch.setattr(life_ellipse, "low_spread", lambda *a: calls.append(a) or spread(*a))
    for c1, c2, c3 in _SPREADS[:4]:
        calls.clear()
        zero_free_log_rho((1.0, c1, c2, c3, 0.0), 6, True)
        assert len(calls) <= 6, (c1, c2, c3, len(calls))


@pytest.mark.parametrize(
    "coefficients", [(1e200, 1e-200, 0.0, 0.0, 0.0), (5.0, 5e-324, 0.0, 0.0, 0.0)]
)
def test_coefficients_whose_shares_of_the_limit_underflow_put_the_zeros_out_of_reach(coefficients):
    # Python would divide 0 by 0 where the generated C gives inf.
    assert zero_free_log_rho(coefficients, 8, False) == (math.inf, math.inf)
