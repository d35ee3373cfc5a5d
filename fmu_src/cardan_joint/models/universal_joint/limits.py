"""The joint's value ranges and the common case's one-comparison-chain input check
(`fits`), from its table."""

from ...framework.values import bounds, value_ranges
from . import variables as table


def _ranges(names, *excluded):
    return value_ranges(table.BY_NAME, names, *excluded)


# The bend angle's own limit is the max_bend_angle parameter, checked apart.
INPUT_RANGES = _ranges(table.INPUTS, "bend_angle")
PARAMETER_RANGES = _ranges(table.PARAMETERS, "max_bend_angle")
PARAMETER_RANGES_WITHOUT_LIFE = _ranges(table.WITHOUT_LIFE.PARAMETERS, "max_bend_angle")
# The fast path of `input_problem` checks |x| <= max, so the ranges must be symmetric.
# (A ranged input it does not name fails tests/unit/test_guards.py, which takes every
# ranged input from the table.)
assert all(low == -high for _, low, high, _ in INPUT_RANGES), "input ranges must be symmetric"
SPEED_LIMIT = bounds(table.BY_NAME["input_speed"])[1]
_ACCELERATION_LIMIT = bounds(table.BY_NAME["input_acceleration"])[1]
_RATE_LIMIT = bounds(table.BY_NAME["bend_angle_rate"])[1]
_BEND_ACCELERATION_LIMIT = bounds(table.BY_NAME["bend_angle_acceleration"])[1]
_LOAD_LIMIT = bounds(table.BY_NAME["load_torque"])[1]


def fits(speed, acceleration, beta, rate, acc, load, guard, step_size) -> bool:
    """The common case, once per FMU step: every input in its range and the bend
    angle below `guard` at both ends of the step, not peaking inside it. NaN fails
    every comparison, so it never fits."""
    # An `if`, not `return a and b ...`: CPython 3.11 specializes a float comparison
    # only when a conditional jump follows it (1.3 k instructions a step).
    if (
        abs(speed) <= SPEED_LIMIT
        and abs(acceleration) <= _ACCELERATION_LIMIT
        and abs(rate) <= _RATE_LIMIT
        and abs(acc) <= _BEND_ACCELERATION_LIMIT
        and abs(load) <= _LOAD_LIMIT
        and abs(beta) < guard
        and abs(beta + step_size * (rate + 0.5 * acc * step_size)) < guard
        and (rate * acc >= 0.0 or -rate / acc >= step_size)
    ):
        return True
    return False
