"""Random steps of any model whose step is written once (docs/codegen.md), drawn
from its variable table alone, so a model that opts in is covered without a
line here: start values, inputs and step sizes around the table's start values
and across its ranges (both signs, the bounds themselves, long steps,
reversals), now and then a value beyond its range or not a number. The states
are those the model reaches: each case starts where the steps before it left
the model, through the runtime's own protocol (`set_step_state`, the moved
inputs, the clock), as after a step taken in C."""

import inspect
import math
import random
from collections.abc import Callable, Iterator, Mapping

from cardan_joint.framework.values import bounds
from cardan_joint.models import Model

BAD = (math.nan, math.inf, -math.inf)
STEP_SIZES = (0.0, -1e-3, math.nan, math.inf, 1e300)
# A long step at a high speed costs a life integral over every turn of it: the
# steps drawn turn at most this far (rad) at the inputs' speeds.
LONGEST_TURN = 200.0


def _bounds(variable) -> tuple[float, float]:
    return bounds(variable) if variable.min is not None else (-math.inf, math.inf)


def typical(rng: random.Random, variable) -> float:
    """An input in use: up to 1.5 times its start value, either sign (a reversal);
    one that starts at zero stays there half the time, or is 1e-3 to 100."""
    start = variable.start
    if start:
        return start * rng.uniform(-1.5, 1.5)
    if rng.random() < 0.5:
        return 0.0
    low, high = _bounds(variable)
    magnitude = 10.0 ** rng.uniform(-3.0, math.log10(min(1e2, max(-low, high))))
    return magnitude if rng.random() < 0.5 else -magnitude


def sized(rng: random.Random, variable, scale: float) -> float:
    """A parameter in use: its start value times `scale` (a design near the
    default, scaled alike in each unit, so a tube's bore stays below its outer
    diameter and a shaft's angle below the guard); one that starts at zero stays
    there half the time, or is 1e-3 to 0.1 of either sign (a propshaft's shaft
    angles and phases: larger ones would put most 4-joint layouts past their
    guards)."""
    if variable.start:
        return variable.start * scale
    if rng.random() < 0.5:
        return 0.0
    return math.copysign(10.0 ** rng.uniform(-3.0, -1.0), rng.uniform(-1.0, 1.0))


def extreme(rng: random.Random, variable) -> float:
    """A bound itself, a magnitude anywhere up to a bound, or zero: within the range."""
    low, high = _bounds(variable)
    finite = [b for b in (low, high) if math.isfinite(b) and b != 0.0] or [1e15]
    bound = rng.choice(finite)
    choices = [bound, math.copysign(10.0 ** rng.uniform(-9.0, math.log10(abs(bound))), bound)]
    return _within(rng.choice([*choices, 0.0]), low, high)


def beyond(rng: random.Random, variable) -> float:
    """Just past a bound, far past it, or not a number."""
    low, high = _bounds(variable)
    past = [math.nextafter(b, math.copysign(math.inf, b or 1.0)) for b in (low, high)]
    far = [2.0 * b if b else -1.0 for b in (low, high)]
    return rng.choice([*(p for p in past + far if math.isfinite(p)), *BAD])


def _within(value: float, low: float, high: float) -> float:
    return min(max(value, low), high)


def input_value(rng: random.Random, variable, bad: float) -> float:
    """An input: beyond its range with probability `bad`, at an extreme with 0.1."""
    draw = rng.random()
    if draw < bad:
        return beyond(rng, variable)
    if draw < bad + 0.1:
        return extreme(rng, variable)
    return _within(typical(rng, variable), *_bounds(variable))


def parameters(rng: random.Random, table) -> dict[str, float]:
    """Every parameter in use; now and then one at an extreme of its range, or
    one beyond it (the parameters then refuse every step)."""
    # A third of the start values to a little more, one factor per unit.
    scales: dict[str, float] = {}
    values = {}
    for n in table.PARAMETERS:
        variable = table.BY_NAME[n]
        scale = scales.setdefault(variable.unit, 10.0 ** rng.uniform(-0.5, 0.04))
        values[n] = _within(sized(rng, variable, scale), *_bounds(variable))
    name = rng.choice(table.PARAMETERS)
    draw = rng.random()
    if draw < 0.1:
        values[name] = extreme(rng, table.BY_NAME[name])
    elif draw < 0.15:
        values[name] = beyond(rng, table.BY_NAME[name])
    return values


def step_size(rng: random.Random, table, inputs: tuple) -> float:
    """Mostly 1e-6 to 10 s (long steps), now and then no valid size at all."""
    if rng.random() < 0.05:
        return rng.choice(STEP_SIZES)
    h = 10.0 ** rng.uniform(-6.0, 1.0)
    speeds = [abs(v) for n, v in zip(table.INPUTS, inputs, strict=True)
              if table.BY_NAME[n].unit == "rad/s" and math.isfinite(v)]  # fmt: skip
    fastest = max(speeds, default=0.0)
    return min(h, LONGEST_TURN / fastest) if fastest > 0.0 else h


class Case:
    """One step: the written step's arguments, and where it takes the model."""

    def __init__(self, model, arguments: list, state_size: int, input_count: int) -> None:
        self.model = model
        self.arguments = arguments
        self.state_size = state_size
        self.input_count = input_count
        self.refused = False

    def follow(self, taken: tuple | None) -> None:
        """Put the model where the step left it (`fast_sync`'s protocol)."""
        self.refused = taken is None
        if taken is None:
            return
        time, h = self.arguments[:2]
        self.model.set_step_state(taken[: self.state_size])
        self.model.set_inputs(taken[self.state_size : self.state_size + self.input_count])
        self.model.time = time + h


def cases(spec: Model, settings: Mapping, seed: int, count: int) -> Iterator[Case]:
    """`count` steps in runs of up to 20, each from a model made with random
    start values; a case's inputs are the moved ones or new ones. The caller
    puts the model where each step left it (`Case.follow`)."""
    rng = random.Random(seed)
    table = spec.table(settings)
    step: Callable = spec.step(settings)  # type: ignore[misc]
    names = tuple(inspect.signature(step).parameters)
    made = 0
    while made < count:
        values = {n: input_value(rng, table.BY_NAME[n], 0.0) for n in table.INPUTS}
        values.update(parameters(rng, table))
        try:
            model = spec.make(settings, **values)
        except ValueError:  # start values the model cannot be made with: no step
            continue
        state_size = len(model.step_state())
        known = names[2 + state_size :]
        time = rng.choice([0.0, rng.uniform(0.0, 1e4)])
        model.start(time)
        case = None
        for _ in range(rng.randint(1, 20)):
            if made == count:
                return
            # New inputs now and then, and after a refusal, as a host would give.
            if rng.random() < 0.3 or (case and case.refused):
                model.set_inputs([input_value(rng, table.BY_NAME[n], 0.03) for n in table.INPUTS])
            inputs = model.inputs()
            h = step_size(rng, table, inputs)
            arguments = [model.time, h, *model.step_state(), *(getattr(model, n) for n in known)]
            made += 1
            case = Case(model, arguments, state_size, len(table.INPUTS))
            yield case
