"""The stepped models' runtime, top to bottom: a step is `SteppedModel.run`
(inputs, `step`, outputs), `step` the checks (`ValueChecks.step_problem`: step
size, parameters, inputs) and then the model's `_advance` and the clock. A
model's folder adds its equations (`models/<name>/model.py`); nothing else is
on the step's path. `ShaftModel` is a model driven at an input shaft kept as
exact revolutions. A model whose step is written once as a function of floats,
which the build translates into C, runs it through `written_step.WrittenStep`
(`rotor_model.RotorModel`: one rotor advanced by the rotor's exact step).

Every stepped model gives the model API (`api.Stepped`) the FMU slaves' core
relies on; the saved state is `values.SavedState`.
"""

import math
from collections.abc import Callable, Iterator
from functools import cache
from operator import attrgetter

from ..physics.revolutions import Turns, advanced, angle_value
from ..variable_schema import Variable
from .api import Table
from .refusal import Reason, Refusal, crossed_limit
from .values import (
    MAX_INCREMENT,
    SavedState,
    bounds,
    overflow,
    set_start_values,
    value_ranges,
)


@cache
def values_getter(names: tuple[str, ...]):
    """A getter of the tuple of `names`' values (attrgetter gives one name's bare value)."""
    getter = attrgetter(*names)
    return getter if len(names) > 1 else lambda model: (getter(model),)


class ValueChecks:
    """Refusals for bad attribute values of a model object with a variable `table`."""

    # What the host model provides: its table, its clock, the parameters' refusal
    # (fixed at `start`) and the check of its inputs over a step.
    table: Table
    time: float
    parameter_fault: Refusal | None

    def input_problem(self, step_size: float = 0.0) -> Refusal | None:
        raise NotImplementedError(f"{type(self).__name__} must check its inputs")

    def inputs(self) -> tuple[float, ...]:
        """The inputs' values, in the table's order."""
        return values_getter(self.table.INPUTS)(self)

    def set_inputs(self, values) -> None:
        """Set every input, `values` in the table's order."""
        for name, value in zip(self.table.INPUTS, values, strict=True):
            setattr(self, name, value)

    def _non_finite_limit(self, name: str, variable: Variable) -> float:
        """The limit a NaN or infinite `name` is reported against: its range's bound."""
        return crossed_limit(getattr(self, name), *bounds(variable))

    def _bad_values(self, names, ranges) -> Iterator[Refusal]:
        """A Refusal for each of `names` not finite or outside its range."""
        by_name = self.table.BY_NAME
        for name in names:
            value = getattr(self, name)
            if not math.isfinite(value):
                variable = by_name[name]
                yield Refusal(
                    Reason.NOT_FINITE,
                    name,
                    value,
                    self._non_finite_limit(name, variable),
                    self.time,
                    variable.unit,
                    kind=variable.causality,
                )
        for name, low, high, unit in ranges:
            value = getattr(self, name)
            if math.isfinite(value) and not low <= value <= high:
                yield Refusal(
                    Reason.OUT_OF_RANGE,
                    name,
                    value,
                    crossed_limit(value, low, high),
                    self.time,
                    unit,
                    {"low": low, "high": high},
                    by_name[name].causality,
                )

    def _value_problem(self, names, ranges) -> Refusal | None:
        """The first bad value, or None."""
        return next(self._bad_values(names, ranges), None)

    def step_problem(self, step_size: float) -> Refusal | None:
        """The Refusal of a step of `step_size` from now, or None."""
        if not (math.isfinite(step_size) and step_size > 0.0):
            return Refusal(Reason.STEP_SIZE, "step_size", step_size, 0.0, self.time, "s")
        if self.parameter_fault:
            return self.parameter_fault.at(self.time)
        return self.input_problem(step_size)


class SteppedModel(ValueChecks, SavedState):
    """The one base of the stepped models: inputs and parameters as attributes
    with the table's start values, their checks, the step (the checks, then
    `_advance`, then the clock) and the saved state (`SavedState`)."""

    table: Table
    _input_ranges: tuple
    _parameter_ranges: tuple

    def __init__(self, **values: float) -> None:
        table = self.table
        set_start_values(self, table, values, type(self).__name__)
        self._input_ranges = value_ranges(table.BY_NAME, table.INPUTS)
        self._parameter_ranges = value_ranges(table.BY_NAME, table.PARAMETERS)
        self.start(0.0)

    def start(self, time: float) -> None:
        """Clock at `time`, state from the parameters, which are checked here, once."""
        self.time = float(time)
        self.parameter_fault = self.parameter_problem()

    def parameter_problem(self) -> Refusal | None:
        return self._value_problem(self.table.PARAMETERS, self._parameter_ranges)

    def input_problem(self, step_size: float = 0.0) -> Refusal | None:
        return self._value_problem(self.table.INPUTS, self._input_ranges)

    def invalid_inputs(self) -> set:
        """Names of the inputs unusable at this instant (non-finite, out of range)."""
        return {r.variable for r in self._bad_values(self.table.INPUTS, self._input_ranges)}

    def step(self, step_size: float) -> Refusal | None:
        """Advance by `step_size`; return None, or the Refusal of the step (then
        nothing has changed, the clock neither)."""
        return self.step_problem(step_size) or self.advance(step_size)

    def run(self, time: float, step_size: float, inputs) -> "tuple | Refusal":
        """The FMU's step: take `inputs` (the table's order), advance `step_size` s
        from `time` and return the outputs and the inputs after it, or the Refusal
        of the step (then only the inputs have changed, the clock neither)."""
        self.set_inputs(inputs)
        before, self.time = self.time, time
        problem = self.step(step_size)
        if problem:
            self.time = before
            return problem
        return self.outputs(), self.inputs()

    def outputs(self) -> tuple:
        raise NotImplementedError(f"{type(self).__name__} must give its outputs")

    def advance(self, step_size: float) -> Refusal | None:
        """`step` once `step_problem` has passed: a layer over this model (the
        compliant drive) checks the inputs once, with its own, then advances."""
        problem = self._advance(step_size)
        if problem:
            return problem
        self.time += step_size
        return None

    def _advance(self, h: float) -> Refusal | None:
        """Move the state `h` s on, or refuse (then nothing has changed)."""
        raise NotImplementedError(f"{type(self).__name__} must advance its state")


class ShaftModel(SteppedModel):
    """A stepped model driven at an input shaft (the joint, the propshaft): the
    shaft's angle kept as exact revolutions, advanced exactly at constant
    acceleration over a step."""

    _speed_limit: float
    _angle: Turns
    input_speed: float
    input_acceleration: float

    def _advance(self, h: float) -> Refusal | None:
        speed, acceleration = self.input_speed, self.input_acceleration
        increment = h * (speed + 0.5 * acceleration * h)
        end_speed = speed + acceleration * h
        if abs(increment) <= MAX_INCREMENT and abs(end_speed) <= self._speed_limit:
            self._angle = advanced(self._angle, increment)
            self.input_speed = end_speed
            return None
        return overflow(speed, acceleration, h, increment, end_speed, self._speed_limit, self.time)

    @property
    def input_angle(self) -> float:
        return angle_value(self._angle)

    def own_state(self) -> dict:
        turns, fraction, fraction_error = self._angle
        return {"turns": turns, "fraction": fraction, "fraction_error": fraction_error}

    def own_state_from(self, state: dict) -> Callable[[], None]:
        angle = (int(state["turns"]), float(state["fraction"]), float(state["fraction_error"]))

        def put() -> None:
            self._angle = angle

        return put
