"""Gauss-Legendre rules on [0, 1] and the Legendre coefficients they give,
tabulated once at import (standard library): the life integral's panels
(`life_integral`) read them as constants.

An n-point rule is exact for polynomials of degree 2n - 1. From the same n
values the coefficients a_k of the interpolating polynomial in Legendre
polynomials P_k(2u - 1) follow exactly (the rule integrates the product of
two degree n - 1 polynomials): a_k = (2k + 1) sum_i w_i P_k(x_i) v_i.
"""

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
