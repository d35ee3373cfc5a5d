"""Functions in the generator's subset (each one a construct it translates) and
functions outside it, for tests/unit/test_codegen.py. Each untranslatable one
names, in `REFUSED`, the construct its message must quote."""

import math
from typing import NamedTuple

SCALE = 0.75
STEPS = 3
# A quadrature rule's constants: tables read by a loop's index.
NODES = (-0.7745966692414834, 0.0, 0.7745966692414834)
WEIGHTS = (0.5555555555555556, 0.8888888888888888, 0.5555555555555556)


def _pair(a: float, b: float) -> tuple[float, float]:
    return a - b, a * b


def _scaled(xp, x, factor=SCALE):
    return xp.atan2(x, factor) + xp.exp(-abs(x))


def loops(x: float, n: int) -> tuple[float, int, float]:
    """while with a condition that calls, for over range with a step, augmented
    assignment, a swap, int arithmetic, true division of two ints and bit
    operations."""
    total = 0.0
    count = 0
    while _pair(total, x)[0] < 10.0 and count < 50:
        total += abs(x) + 0.1
        count = count + 1
    for k in range(n, -STEPS, -2):
        total = total - k * SCALE
    a, b = total, x
    a, b = b, a
    return a + b / 3.0, (count * 7 + n) & 5 ^ 3 | (count << 2) >> 1, (count + n) / 7


def choices(x: float, y: float) -> tuple:
    """min and max as Python picks (NaN too), a conditional expression, math,
    tuple slicing, negative indices, concatenation, keyword arguments."""
    first = max(x, y, 0.5)
    second = min(y, x)
    pair = _pair(b=y, a=x)
    both = pair + (first, second)
    sign = -1.0 if math.floor(x) & 1 == 0 and x < y else 1.0
    return both[1:] + (both[-4], sign * _scaled(math, x), math.isfinite(y), math.trunc(y))


def quadrature(a: float, b: float) -> float:
    """Constant tables indexed by a loop's int, len() of a table, ** of an int."""
    half = 0.5 * (b - a)
    total = 0.0
    for k in range(len(NODES)):
        x = a + half * (1.0 + NODES[k])
        total += WEIGHTS[k] * math.sin(x) * x**k
    return half * total + WEIGHTS[-1]


# Rules of several sizes, indexed by their size (a tuple of tables of any lengths).
RULES = ((), (0.5,), (0.2113248654051871, 0.7886751345948129))
# Their weights: rows of the same sizes, whose C shares RULES' row starts.
RULE_WEIGHTS = ((), (1.0,), (0.5, 0.5))


class Rule(NamedTuple):
    scale: float
    power: float
    count: int


def _weighted(rule: Rule, x):
    return rule.scale * abs(x) ** rule.power + float(rule.count)


def _apply(function, pair, k: int):
    """A function passed as an argument, bound when translated; `pair` takes the
    caller's tuple."""
    return function(pair[0], pair[1])[1] + RULES[2][k]


def shapes(x: float, y: float) -> tuple:
    """A table of rows, a NamedTuple built and read by field, a function passed
    as an argument, a tuple spread into a call and into a tuple, math.log."""
    total = 0.0
    for n in range(1, len(RULES)):
        for k in range(n):
            total += RULE_WEIGHTS[n][k] * RULES[n][k] * x
    rule = Rule(0.5, 1.5, 2)
    pair = (x, y)
    spread = (*_pair(*pair), math.log(abs(y) + 1.0))
    return (total, _weighted(rule, y), _apply(_pair, pair, 1), _apply(_pair, pair, 0),
            *spread)  # fmt: skip


def extremes(x: float, y: float) -> tuple[float, float, float, float]:
    """Python keeps the first of equals and a NaN only where it comes first."""
    return max(x, y), min(x, y), max(y, x), min(y, x)


RECORD = 2  # items per joint in `over_joints`' layout


def _accumulated(values):
    """A tuple built item by item over a tuple's positions; its items' sum."""
    built = ()
    total = 0.0
    for k in range(len(values) - 1, -1, -1):
        built = (values[k] * k,) + built
        total = total + built[0]
    return built + (total,)


def over_joints(x: float, y: float) -> tuple:
    """Loops over a tuple's positions, unrolled: constant indices computed from
    the loop's variable and len(), a tuple grown by an item a copy, a value
    carried from copy to copy, a kept loop and an if inside, a caller-shaped
    tuple of each length, the variable's last value after the loop."""
    layout = (x, y, x * y, y - x, 0.5 * x, -y)
    speeds = ()
    w = 1.0
    for k in range(len(layout) // RECORD):
        w = w * layout[RECORD * k] + layout[RECORD * k + 1]
        if w > 0.0:
            w = -0.5 * w
        for _ in range(k):
            w = w + 0.25
        speeds = speeds + (w, w * k)
    last = k
    return _accumulated(speeds) + _accumulated(layout[1:-1]) + (last * w,) + speeds[-2:]


def misordered(
    time: float,
    h: float,
    turns: int,
    fraction: float,
    fraction_error: float,
    phase_turns: int,
    phase_fraction: float,
    phase_error: float,
    parameters_valid: bool,
    input_acceleration: float,
    input_speed: float,
    bend_angle: float,
    bend_angle_rate: float,
    bend_angle_acceleration: float,
    load_torque: float,
) -> tuple[float, float]:
    """A joint step's parameters with two inputs swapped: off the runtime's order."""
    return input_speed, input_acceleration


def with_list(x: float) -> float:
    values = [x, x]
    return values[0]


def with_hypot(x: float) -> float:
    return math.hypot(x, 1.0)


def with_object(x: float) -> float:
    return x.real


def with_floor_division(n: int) -> int:
    return n // 2


def with_none(x: float) -> float:
    if x > 0.0:
        return x
    return None  # type: ignore[return-value]


def with_retyped(x: float) -> float:
    y = 1
    y = x
    return y


def with_exit_in_unrolled(x: float) -> float:
    pair = (x, x)
    for k in range(len(pair)):
        if pair[k] > 0.0:
            break
    return x


def with_tuple_retyped_in_branch(x: float) -> tuple:
    pair = (x, x)
    if x > 0.0:
        pair = pair + (x,)
    return pair


def with_index_by_variable(x: float, n: int) -> float:
    pair = (x, x)
    return pair[n]


def with_empty_tuple_returned(x: float) -> tuple:
    nothing = ()
    return nothing


REFUSED = {
    with_exit_in_unrolled: "break",
    with_tuple_retyped_in_branch: "pair = pair + (x,)",
    with_index_by_variable: "pair[n]",
    with_empty_tuple_returned: "return nothing",
    with_list: "[x, x]",
    with_hypot: "math.hypot(x, 1.0)",
    with_object: "x.real",
    with_floor_division: "n // 2",
    with_none: "return None",
    with_retyped: "y = x",
}
