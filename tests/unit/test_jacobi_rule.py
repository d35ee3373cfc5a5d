"""The Gauss-Jacobi rules for the weight u^12 on [0, 1] (`quadrature`) that
life's panels substituted at a torque zero take (`life_panel.rule_sizing`):
against exact moments, against scipy's independent derivation (Golub-Welsch),
their Legendre-coefficient tables against mpmath's inverse of the Legendre
Vandermonde matrix; and the
guards of the rule's choice and of its bound, each failing without them."""

import math

import mpmath
import pytest
import scipy.special
from life_reference import damage

from cardan_joint.physics.life import life_rule, step_damage
from cardan_joint.physics.life_panel import (
    error_budget,
    rule_sizing,
    weighted_share,
    zero_free_on,
)
from cardan_joint.physics.quadrature import (
    JACOBI_FIRST,
    JACOBI_LAST,
    JACOBI_MEAN,
    JACOBI_NODES,
    JACOBI_POWER,
    JACOBI_SECOND,
    JACOBI_THIRD,
    JACOBI_WEIGHTS,
    JACOBI_ZEROTH,
    MAX_POINTS,
    MIN_POINTS,
)

POINTS = range(MIN_POINTS, MAX_POINTS + 1)


@pytest.mark.parametrize("n", POINTS)
def test_the_rule_integrates_u12_times_each_power_below_2n_exactly(n):
    nodes, weights = JACOBI_NODES[n], JACOBI_WEIGHTS[n]
    assert len(nodes) == len(weights) == n
    assert all(0.0 < a < b < 1.0 for a, b in zip(nodes, nodes[1:]))
    assert all(w > 0.0 for w in weights)
    for k in range(2 * n):
        got = math.fsum(w * u**k for u, w in zip(nodes, weights))
        assert got == pytest.approx(1.0 / (JACOBI_POWER + 1.0 + k), rel=1e-13, abs=0.0), k
    assert math.fsum(JACOBI_MEAN[n]) == pytest.approx(1.0, rel=1e-14, abs=0.0)


@pytest.mark.parametrize("n", POINTS)
def test_the_rule_is_scipys_gauss_jacobi_rule_mapped_onto_0_1(n):
    # roots_jacobi(n, alpha, beta): weight (1 - x)^alpha (1 + x)^beta on [-1, 1]
    x, w = scipy.special.roots_jacobi(n, 0.0, JACOBI_POWER)
    assert JACOBI_NODES[n] == pytest.approx(0.5 * (1.0 + x), rel=0.0, abs=2e-15)
    scale = 2.0 ** (JACOBI_POWER + 1.0)
    assert JACOBI_WEIGHTS[n] == pytest.approx(w / scale, rel=1e-12, abs=0.0)


@pytest.mark.parametrize("n", POINTS)
def test_the_tables_are_the_rows_of_the_inverse_legendre_vandermonde_matrix(n):
    """a = V^-1 v, V_ik = P_k(2 u_i - 1), solved by mpmath at 40 digits. The
    nodes crowd towards u = 1 (the weight u^12), so the interpolant's
    coefficients weigh the values by up to 1e6 (n = 20) with cancellation:
    tabulated in doubles they hold to 1e-10 of their row's largest, far
    inside the check's shares (0.8 and 0.1 of a_0)."""
    nodes = JACOBI_NODES[n]
    with mpmath.workdps(40):
        vandermonde = mpmath.matrix(n, n)
        for i, u in enumerate(nodes):
            for k in range(n):
                vandermonde[i, k] = mpmath.legendre(k, 2 * mpmath.mpf(u) - 1)
        inverse = vandermonde**-1
        tables = (
            (JACOBI_ZEROTH, 0), (JACOBI_FIRST, 1), (JACOBI_SECOND, 2), (JACOBI_THIRD, 3),
            (JACOBI_LAST, n - 1),
        )  # fmt: skip
        for table, degree in tables:
            row = [float(inverse[degree, i]) for i in range(n)]
            largest = max(abs(c) for c in row)
            assert table[n] == pytest.approx(row, rel=0.0, abs=1e-10 * largest), degree


def test_only_a_panel_that_divides_every_joint_at_the_tabulated_power_is_weighted():
    budget = error_budget(10.0 / 3.0)
    q, gamma = 3.0, 3.0 * (10.0 / 3.0 + 1.0) - 1.0
    weighted, stretch, degree, sized = rule_sizing(1, 0b1, 1, q, gamma, budget)
    assert weighted and stretch == q and degree == 0.0 and sized > budget
    assert rule_sizing(-1, 0b11, 2, q, gamma, budget)[0]
    # one joint of two divided: the other's integrand is not u^12 times a smooth factor
    assert rule_sizing(1, 0b01, 2, q, gamma, budget) == (False, q, gamma, budget)
    assert rule_sizing(0, 0, 1, q, gamma, budget) == (False, 1.0, 0.0, budget)
    assert rule_sizing(1, 0b1, 1, 3.0, 11.0, budget) == (False, 3.0, 11.0, budget)


def test_a_reversal_at_another_exponent_keeps_gauss_legendre_and_is_exact():
    """p = 3: gamma = 11, which the u^12 rule would take for u^12 (2e-2 off):
    an inertial torque, 0.5 rad of bend, changing sign over the step."""
    rule = life_rule(1000.0, 1.5e6, 3.0, math.radians(3.0))
    case = (0.3, 0.5, 200.0, 0.0, 0.0, 0.0, (0.02, 0.03, 0.05), 0.0)
    psi, b, w, a, rb, ab, inertia, load = case
    got = step_damage(rule, 0.01, psi, b, w, a, rb, ab, inertia, load)
    assert got == pytest.approx(damage(case, 0.01, rule), rel=1e-9, abs=0.0)


def test_a_weighted_panels_share_of_a0_leaves_room_for_its_weighted_mean():
    assert weighted_share(2.0, 3.0) == 2.0
    assert weighted_share(-2.0, -2.0) == pytest.approx(-2.0, rel=1e-15)
    # |a_0| + 0.9 share = 1.9 |b_0|: the maximum stays within 1.9 of the weighted mean
    share = weighted_share(2.0, 1.5)
    assert 2.0 + 0.9 * share == pytest.approx(1.9 * 1.5, rel=1e-15)
    assert weighted_share(-2.0, 0.5) == -0.0 and weighted_share(2.0, 0.5) == 0.0
    # none left: no ellipse is zero-free, however flat the coefficients
    assert not zero_free_on(0.5, (0.0, 0.0, 0.0, 0.0, 0.0), 8, True)
