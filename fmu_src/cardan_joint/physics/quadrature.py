"""Gauss-Lobatto rules on [-1, 1], computed once at import (standard library).

An n-point rule is exact for polynomials of degree 2n - 3 and includes both
ends, which the life integral samples anyway to see the torque change sign.
"""

import math
from functools import cache


def _legendre(n, x):
    """(P_n(x), P_n'(x)) by the three-term recurrence (|x| < 1)."""
    p0, p1 = 1.0, x
    for k in range(2, n + 1):
        p0, p1 = p1, ((2 * k - 1) * x * p1 - (k - 1) * p0) / k
    return p1, n * (x * p1 - p0) / (x * x - 1.0)


@cache
def lobatto_rule(points: int) -> tuple[tuple[float, ...], tuple[float, ...]]:
    """(nodes, weights) of the `points`-point Gauss-Lobatto rule, nodes ascending."""
    n = points - 1
    inner = []
    for k in range(1, n):
        # Interior nodes: the roots of P_n', by Newton from Chebyshev-Gauss-Lobatto points.
        x = -math.cos(math.pi * k / n)
        for _ in range(100):
            p, dp = _legendre(n, x)
            # P_n'' from Legendre's equation: (1 - x^2) P'' = 2 x P' - n (n + 1) P.
            d2p = (2.0 * x * dp - n * (n + 1) * p) / (1.0 - x * x)
            step = dp / d2p
            x -= step
            if abs(step) < 1e-17:
                break
        inner.append(x)
    nodes = (-1.0, *inner, 1.0)
    weights = tuple(
        2.0 / (n * (n + 1) * _legendre(n, x)[0] ** 2) if abs(x) < 1 else 2.0 / (n * (n + 1))
        for x in nodes
    )
    return nodes, weights


@cache
def gauss_unit_rule(points: int) -> tuple[tuple[float, float], ...]:
    """((u, w), ...) of the `points`-point Gauss-Legendre rule on [0, 1] (exact
    for degree 2 points - 1; weights summing to 1): the one-panel step, which
    needs no ends."""
    rule = []
    for k in range(points):
        x = math.cos(math.pi * (k + 0.75) / (points + 0.5))  # Tricomi's first guess
        for _ in range(100):
            p, dp = _legendre(points, x)
            step = p / dp
            x -= step
            if abs(step) < 1e-17:
                break
        p, dp = _legendre(points, x)
        rule.append((0.5 * (1.0 - x), 1.0 / ((1.0 - x * x) * dp * dp)))
    return tuple(rule)


def panel_nodes(nodes, weights, a, b):
    """(t, w) pairs of a rule's nodes mapped onto [a, b] (ends exact)."""
    half, mid = 0.5 * (b - a), 0.5 * (a + b)
    last = len(nodes) - 1
    return [
        (a if i == 0 else b if i == last else mid + half * x, w)
        for i, (x, w) in enumerate(zip(nodes, weights))
    ]
