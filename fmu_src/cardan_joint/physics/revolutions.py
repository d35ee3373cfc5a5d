"""An angle kept as whole revolutions plus a compensated fraction.

A float angle of 6e6 rad (a million revolutions) resolves only 1e-9 rad, and a
step-by-step sum would also round each increment against the large total.
Keeping `turns` (an exact integer) apart from a double-double fraction in
[0, 2 pi) makes every step add to a small number and every reduction by 2 pi
exact, so the input angle does not drift however long the run.
"""

import math
from typing import NamedTuple

# 2 pi as a double-double: the double nearest to it and the rest.
TWO_PI_HI = 2.0 * math.pi
TWO_PI_LO = 2.4492935982947064e-16  # 2 pi - TWO_PI_HI
_SPLITTER = 134217729.0  # 2**27 + 1, Dekker's split


# What a stepped model keeps: (turns, fraction, fraction_error) as a plain tuple,
# which `RevolutionAngle` names for everyone else (a NamedTuple costs a
# Python-level construction at every step).
Turns = tuple[int, float, float]


class RevolutionAngle(NamedTuple):
    turns: int
    fraction: float
    fraction_error: float = 0.0

    def __float__(self) -> float:
        return angle_value(self)


def angle_value(angle: Turns) -> float:
    """The angle as the float nearest to it (two roundings at most)."""
    turns, fraction, fraction_error = angle
    product, product_error = _two_product(float(turns), TWO_PI_HI)
    total, sum_error = _two_sum(product, fraction)
    return total + (sum_error + product_error + fraction_error + turns * TWO_PI_LO)


# The error-free transformations (Knuth's two-sum, Dekker's split and product):
# each result pair is the exact sum or product. Their exactness rests on every
# operation rounding once, as written: C generated from them keeps that order
# (docs/codegen.md).


def _two_sum(a: float, b: float) -> tuple[float, float]:
    s = a + b
    bb = s - a
    return s, (a - (s - bb)) + (b - bb)


def _split(a: float) -> tuple[float, float]:
    t = _SPLITTER * a
    hi = t - (t - a)
    return hi, a - hi


def _two_product(a: float, b: float) -> tuple[float, float]:
    p = a * b
    a_hi, a_lo = _split(a)
    b_hi, b_lo = _split(b)
    return p, ((a_hi * b_hi - p) + a_hi * b_lo + a_lo * b_hi) + a_lo * b_lo


def _shift(turns: int, fraction: float, error: float, whole: int) -> Turns:
    """Move `whole` turns from the fraction to the counter, exactly."""
    product, product_error = _two_product(float(whole), TWO_PI_HI)
    fraction, sum_error = _two_sum(fraction, -product)
    return turns + whole, fraction, error + sum_error - product_error - whole * TWO_PI_LO


def _normalized(turns: int, fraction: float, error: float) -> Turns:
    """(turns, fraction, error) with 0 <= fraction <= TWO_PI_HI, the error term
    carrying the rest (a true value just below 2 pi may round its leading part
    up to TWO_PI_HI)."""
    fraction, error = _two_sum(fraction, error)
    if not 0.0 <= fraction <= TWO_PI_HI:
        turns, fraction, error = _shift(turns, fraction, error, math.floor(fraction / TWO_PI_HI))
        fraction, error = _two_sum(fraction, error)
        if fraction < 0.0 or fraction > TWO_PI_HI:  # the floor landed one off
            turns, fraction, error = _shift(turns, fraction, error, -1 if fraction < 0.0 else 1)
            fraction, error = _two_sum(fraction, error)
    return turns, fraction, error


def split_turns(angle: float) -> Turns:
    """`split_angle` as a stepped model keeps it (a plain tuple: unpacking a
    NamedTuple, once per step, takes CPython's generic iterator path)."""
    return _normalized(0, float(angle), 0.0)


def split_angle(angle: float) -> RevolutionAngle:
    return RevolutionAngle(*split_turns(angle))


def advance(angle: Turns, increment: float) -> RevolutionAngle:
    return RevolutionAngle(*advanced(angle, increment))


def advanced(angle: Turns, increment: float) -> Turns:
    """`advance` on a stepped model's plain tuple."""
    turns, fraction, fraction_error = angle
    total, sum_error = _two_sum(fraction, increment)
    return _normalized(turns, total, fraction_error + sum_error)
