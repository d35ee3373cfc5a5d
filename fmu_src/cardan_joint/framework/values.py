"""What the stepped models' checks and state are built of (`stepped.py`): the
ranges and start values read from a variable table, the refusals of an angle
limit and of an overflowing step, and the saved state in its one format."""

import math
from collections.abc import Callable, Mapping

from ..names import unknown
from ..variable_schema import Variable
from .api import Table
from .refusal import Reason, Refusal

# Beyond 1e15 rad a float has no fractional digits left: the pin's position
# after such a step is undefined, and the exact turn arithmetic would overflow.
MAX_INCREMENT = 1e15
HALF_PI = 0.5 * math.pi


Range = tuple[str, float, float, str]


def value_ranges(by_name: Mapping[str, Variable], names, *excluded: str) -> tuple[Range, ...]:
    """(name, min, max, unit) of each of `names` that has a range in the table."""
    return tuple(
        (n, *bounds(by_name[n]), by_name[n].unit)
        for n in names
        if by_name[n].min is not None and n not in excluded
    )


def bounds(variable: Variable) -> tuple[float, float]:
    """(min, max) of a checked variable; only outputs may have a one-sided range."""
    if variable.min is None or variable.max is None:
        raise ValueError(
            f"{variable.name} ({variable.causality}) is checked, so it needs both "
            f"min and max, not min={variable.min}, max={variable.max}"
        )
    return variable.min, variable.max


class UnknownVariableError(TypeError):
    """A start value for a name that is no input or parameter of the model."""


def set_start_values(model, table: Table, values: Mapping[str, float], what: str) -> None:
    """Every input and parameter of `model` from the table's start values, then
    `values`; an unknown name is an UnknownVariableError naming `what` (the
    model) and the nearest valid names (the one check of start-value names)."""
    settable = set(table.INPUTS) | set(table.PARAMETERS)
    strangers = sorted(set(values) - settable)
    if strangers:
        kind = f"input or parameter of the {what}"
        raise UnknownVariableError(unknown(strangers[0], settable, kind))
    for name, value in {**table.start_values(), **values}.items():
        setattr(model, name, float(value))


def angle_limit_problem(reason, name: str, value: float, time: float) -> Refusal | None:
    """The Refusal of an angle limit parameter not strictly between 0 and pi/2
    (where a joint locks), or None: the one guard of max_bend_angle and
    max_working_angle."""
    if 0.0 < value < HALF_PI:
        return None
    limit = 0.0 if value <= 0.0 else HALF_PI
    return Refusal(reason, name, value, limit, time, "rad", kind="parameter")


def shaft_moves(h, speed, acceleration, speed_limit) -> bool:
    """Whether a shaft at `speed` and constant `acceleration` may take a step of
    `h` s: its angle's increment within MAX_INCREMENT and its end speed within
    `speed_limit` (what `overflow` refuses otherwise). NaN fails both."""
    increment = h * (speed + 0.5 * acceleration * h)
    end_speed = speed + acceleration * h
    return abs(increment) <= MAX_INCREMENT and abs(end_speed) <= speed_limit


def overflow(speed, acceleration, h, increment, end_speed, speed_limit, time) -> Refusal:
    """The Refusal of a step whose angle `increment` or `end_speed` overflows."""
    details = {"input_speed": speed, "input_acceleration": acceleration, "step_size": h}
    if not abs(increment) <= MAX_INCREMENT:
        return Refusal(
            Reason.ANGLE_OVERFLOW, "input_angle", increment, MAX_INCREMENT, time, "rad", details
        )
    return Refusal(
        Reason.SPEED_OVERFLOW, "input_speed", end_speed, speed_limit, time, "rad/s", details
    )


class SavedState:
    """state()/restore() of every stepped model, in one format: the table's inputs
    and parameters, the model's own state (`own_state`: e.g. a rotor's speed and
    angle, an input shaft's exact revolutions) and the clock. `start(time)`
    re-derives everything else."""

    table: Table
    time: float

    def start(self, time: float) -> None:
        raise NotImplementedError(f"{type(self).__name__} must define its start")

    def own_state(self) -> dict:
        """The model's state beyond its inputs, parameters and clock (none here)."""
        return {}

    def own_state_from(self, state: dict) -> Callable[[], None]:
        """Read `own_state`'s values from `state` (raising if they are malformed) and
        return what puts them in place once the model has started."""
        return lambda: None

    def _saved_names(self) -> tuple[str, ...]:
        return self.table.INPUTS + self.table.PARAMETERS

    def state(self) -> dict:
        """Everything that defines the model, as JSON-serialisable values."""
        values = {name: getattr(self, name) for name in self._saved_names()}
        values.update(self.own_state())
        values["time"] = self.time
        return values

    def restore(self, state: dict) -> None:
        """Take a `state()`; all or nothing (a malformed state raises and changes nothing)."""
        values = {name: float(state[name]) for name in self._saved_names()}
        time = float(state["time"])
        put_own_state = self.own_state_from(state)
        for name in self.table.INPUTS + self.table.PARAMETERS:
            setattr(self, name, values[name])
        self.start(time)
        put_own_state()
