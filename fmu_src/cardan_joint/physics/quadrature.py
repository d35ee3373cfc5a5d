"""Gauss-Legendre rules on [0, 1], Gauss-Jacobi rules for the weight u^12 on
[0, 1], and the Legendre coefficients of the polynomial through either's
values, tabulated once at import (standard library): the life integral's
panels (`life_nodes`) read them as constants.

An n-point rule is exact for polynomials of degree 2n - 1 (times its weight).
From the same n values the coefficients a_k of the interpolating polynomial
in Legendre polynomials P_k(2u - 1) follow exactly: on Gauss-Legendre nodes
a_k = (2k + 1) sum_i w_i P_k(x_i) v_i (the rule integrates the product of two
degree n - 1 polynomials); on Gauss-Jacobi nodes a_k = (2k + 1) sum_i v_i
int_0^1 P_k(2u - 1) l_i(u) du, l_i the Lagrange basis, whose integrals the
n-point Gauss-Legendre rule gives exactly.

The Gauss-Jacobi rule takes the power u^gamma, gamma = q (p + 1) - 1, that a
panel substituted at a torque zero carries (`life_panel`), into its weight:
its points then go to the smooth factor alone. gamma is 12 at the catalogue
exponent p = 10/3 (q = 3); other exponents keep Gauss-Legendre there.
"""

import functools
import math

MIN_POINTS = 4
MAX_POINTS = 20


def _legendre(n, x):
    """(P_n(x), P_n'(x)) by the three-term recurrence (|x| < 1)."""
    p0, p1 = 1.0, x
    for k in range(2, n + 1):
        p0, p1 = p1, ((2 * k - 1) * x * p1 - (k - 1) * p0) / k
    return p1, n * (x * p1 - p0) / (x * x - 1.0)


def _legendre_value(k, x):
    if k == 0:
        return 1.0
    return _legendre(k, x)[0]


@functools.cache
def gauss_rule(points: int) -> tuple[tuple[float, ...], tuple[float, ...]]:
    """(nodes, weights) of the `points`-point Gauss-Legendre rule on [0, 1],
    nodes ascending, weights summing to 1."""
    nodes, weights = [], []
    for k in range(points):
        x = -math.cos(math.pi * (k + 0.75) / (points + 0.5))  # Tricomi's first guess
        for _ in range(100):
            p, dp = _legendre(points, x)
            step = p / dp
            x -= step
            if abs(step) < 1e-17:
                break
        p, dp = _legendre(points, x)
        nodes.append(0.5 * (1.0 + x))
        weights.append(1.0 / ((1.0 - x * x) * dp * dp))
    return tuple(nodes), tuple(weights)


def _coefficient_weights(points: int, degree: int) -> tuple[float, ...]:
    """c_i with a_degree = sum_i c_i v_i for the `points`-point rule's values v_i."""
    nodes, weights = gauss_rule(points)
    return tuple(
        (2 * degree + 1) * w * _legendre_value(degree, 2.0 * u - 1.0)
        for u, w in zip(nodes, weights)
    )


def _jacobi_matrix(points: int, gamma: float) -> tuple[list[float], list[float]]:
    """(diagonal, squared off-diagonal) of the Jacobi matrix of the polynomials
    orthogonal for u^gamma on [0, 1]: the classical recurrence of P^(0, gamma)
    on [-1, 1] (x = 2u - 1), halved and quartered onto [0, 1]."""
    diagonal, off = [], [0.0]
    for k in range(points):
        s = 2.0 * k + gamma
        diagonal.append(0.5 * (1.0 + gamma * gamma / (s * (s + 2.0))))
        if k > 0:
            off.append(k * k * (k + gamma) ** 2 / (s * s * (s + 1.0) * (s - 1.0)))
    return diagonal, off


def _below(x, diagonal, off) -> int:
    """How many eigenvalues of the Jacobi matrix lie below x (Sturm's count on
    the pivots of J - x)."""
    count, pivot = 0, 1.0
    for k, d in enumerate(diagonal):
        pivot = d - x - (off[k] / pivot if k > 0 else 0.0)
        if pivot == 0.0:
            pivot = -1e-300
        count += pivot < 0.0
    return count


def jacobi_rule(points: int, gamma: float) -> tuple[tuple[float, ...], tuple[float, ...]]:
    """(nodes, weights) of the `points`-point Gauss rule for the weight u^gamma
    on [0, 1], nodes ascending, weights summing to 1 / (gamma + 1): the nodes
    are the Jacobi matrix's eigenvalues, each bisected by Sturm's count to the
    last bit; the weights 1 / sum_k p_k(x)^2 over the orthonormal p_k."""
    diagonal, off = _jacobi_matrix(points, gamma)
    nodes: list[float] = []
    weights: list[float] = []
    for i in range(points):
        lo, hi = nodes[-1] if nodes else 0.0, 1.0
        while True:
            mid = 0.5 * (lo + hi)
            if mid in (lo, hi):
                break
            if _below(mid, diagonal, off) > i:
                hi = mid
            else:
                lo = mid
        before, value = 0.0, math.sqrt(gamma + 1.0)
        total = value * value
        for k in range(points - 1):
            step = math.sqrt(off[k + 1])
            before, value = value, ((mid - diagonal[k]) * value - math.sqrt(off[k]) * before) / step
            total += value * value
        nodes.append(mid)
        weights.append(1.0 / total)
    return tuple(nodes), tuple(weights)


def _lagrange(nodes, i, u):
    """The Lagrange basis polynomial of node i through `nodes`, at u."""
    value = 1.0
    for m, node in enumerate(nodes):
        if m != i:
            value *= (u - node) / (nodes[i] - node)
    return value


def _interpolant_weights(nodes, degree: int) -> tuple[float, ...]:
    """c_i with a_degree = sum_i c_i v_i for the polynomial through (nodes, v):
    (2 degree + 1) int_0^1 P_degree(2u - 1) l_i(u) du by the Gauss-Legendre
    rule of as many points, exact for the degree at most 2n - 2."""
    legendre_nodes, legendre_weights = gauss_rule(len(nodes))
    weighted = [
        (2 * degree + 1) * w * _legendre_value(degree, 2.0 * y - 1.0)
        for y, w in zip(legendre_nodes, legendre_weights)
    ]
    return tuple(
        math.fsum(c * _lagrange(nodes, i, y) for y, c in zip(legendre_nodes, weighted))
        for i in range(len(nodes))
    )


def _table(make):
    return tuple(make(n) if n >= MIN_POINTS else () for n in range(MAX_POINTS + 1))


# Indexed by the number of points n (empty below MIN_POINTS).
GAUSS_NODES = _table(lambda n: gauss_rule(n)[0])
GAUSS_WEIGHTS = _table(lambda n: gauss_rule(n)[1])
# The weights giving the Legendre coefficients a_1, a_2, a_3 and a_(n-1) (the
# highest the rule resolves) from the values at the nodes.
FIRST_COEFFICIENT = _table(lambda n: _coefficient_weights(n, 1))
SECOND_COEFFICIENT = _table(lambda n: _coefficient_weights(n, 2))
THIRD_COEFFICIENT = _table(lambda n: _coefficient_weights(n, 3))
LAST_COEFFICIENT = _table(lambda n: _coefficient_weights(n, n - 1))

# The power a panel substituted at a torque zero carries at p = 10/3, q = 3.
JACOBI_POWER = 12.0
_JACOBI = _table(lambda n: jacobi_rule(n, JACOBI_POWER))
JACOBI_NODES = tuple(rule[0] if rule else () for rule in _JACOBI)
JACOBI_WEIGHTS = tuple(rule[1] if rule else () for rule in _JACOBI)
# Weights giving the weighted mean (gamma + 1) sum_i W_i v_i, and the Legendre
# coefficients a_0..a_3, a_(n-1) of the polynomial through the values.
JACOBI_MEAN = tuple(tuple((JACOBI_POWER + 1.0) * w for w in row) for row in JACOBI_WEIGHTS)
JACOBI_ZEROTH = _table(lambda n: _interpolant_weights(JACOBI_NODES[n], 0))
JACOBI_FIRST = _table(lambda n: _interpolant_weights(JACOBI_NODES[n], 1))
JACOBI_SECOND = _table(lambda n: _interpolant_weights(JACOBI_NODES[n], 2))
JACOBI_THIRD = _table(lambda n: _interpolant_weights(JACOBI_NODES[n], 3))
JACOBI_LAST = _table(lambda n: _interpolant_weights(JACOBI_NODES[n], n - 1))


def node_of(points: int, i: int, weighted: bool):
    """Unit node i of the `points`-point rule: Gauss-Jacobi's if `weighted`."""
    return JACOBI_NODES[points][i] if weighted else GAUSS_NODES[points][i]
