"""The one stepped-model base every model's physics derives from: `SteppedModel`
(inputs and parameters as attributes with the table's start values, their
checks, the step and the saved state), `ShaftModel` (a model driven at an
input shaft kept as exact revolutions) and `RotorModel` (one rotor advanced by
`exact_rotor_step`, the exact step of a driven inertia).

Every stepped model gives the model API (`api.Stepped`) the FMU slaves' core
relies on; the value and step-size checks are the joint's (`values.ValueChecks`).
"""

import math
from collections.abc import Callable
from functools import cache
from operator import attrgetter
from typing import Any

from .refusal import Refusal
from .revolutions import Turns, advanced, angle_value
from .values import (
    MAX_INCREMENT,
    SavedState,
    Table,
    ValueChecks,
    bounds,
    overflow,
    set_start_values,
    value_ranges,
)


@cache
def _getter(names: tuple[str, ...]):
    """A getter of the tuple of `names`' values (attrgetter gives one name's bare value)."""
    getter = attrgetter(*names)
    return getter if len(names) > 1 else lambda model: (getter(model),)


def _phi2(z: float) -> float:
    """(exp(z) - 1 - z) / z^2, without the cancellation of that formula near z = 0."""
    if abs(z) > 0.05:
        return (math.expm1(z) - z) / (z * z)
    # Taylor series 1/2 + z/6 + ... to z^8: truncation below 1e-19 for |z| <= 0.05.
    total, term = 0.0, 1.0
    for k in range(2, 11):
        term /= k
        total += term
        term *= z
    return total


def exact_rotor_step(speed: float, inertia: float, damping: float, torque: float, h: float):
    """(speed, angle increment) after `h` s of J w' = torque - damping w, the torque
    held: exact for any damping >= 0, zero included (then uniform acceleration).

    With a = (torque - damping w) / J and z = -damping h / J:
    w(h) = w + a h (e^z - 1)/z and the angle grows by w h + a h^2 (e^z - 1 - z)/z^2.
    """
    acceleration = (torque - damping * speed) / inertia
    z = -damping * h / inertia
    # expm1 keeps full precision when h is much shorter than the time constant.
    phi1 = math.expm1(z) / z if z else 1.0
    return speed + acceleration * h * phi1, h * (speed + acceleration * h * _phi2(z))


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

    def inputs(self) -> tuple[float, ...]:
        """The inputs' values, in the table's order."""
        return _getter(self.table.INPUTS)(self)

    def set_inputs(self, values) -> None:
        """Set every input, `values` in the table's order."""
        for name, value in zip(self.table.INPUTS, values, strict=True):
            setattr(self, name, value)

    def step(self, step_size: float) -> Refusal | None:
        """Advance by `step_size`; return None, or the Refusal of the step (then
        nothing has changed, the clock neither)."""
        # `advance` inlined: this runs once per FMU step.
        problem = self.step_problem(step_size) or self._advance(step_size)
        if problem:
            return problem
        self.time += step_size
        return None

    def run(self, time: float, step_size: float, inputs) -> "tuple | Refusal":
        """The FMU's step: take `inputs` (the table's order), advance `step_size` s
        from `time` and return the outputs after it, or the Refusal of the step
        (then only the inputs have changed, the clock neither)."""
        self.set_inputs(inputs)
        before, self.time = self.time, time
        problem = self.step(step_size)
        if problem:
            self.time = before
            return problem
        return self.outputs()

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


class RotorModel(SteppedModel):
    """A stepped model whose state is one rotor (the motor, the inertia load):
    speed and angle from their start parameters, advanced by the exact rotor
    step, a speed beyond `speed_start`'s range refused with `_SPEED_REASON`."""

    _SPEED_REASON: Any
    _TORQUE_INPUT: str  # the input named in the speed refusal
    speed_start: float
    angle_start: float
    speed: float
    angle: float

    def start(self, time: float) -> None:
        super().start(time)
        valid = not self.parameter_fault
        self.speed = self.speed_start if valid else 0.0
        self.angle = self.angle_start if valid else 0.0

    def own_state(self) -> dict:
        return {"speed": self.speed, "angle": self.angle}

    def own_state_from(self, state: dict) -> Callable[[], None]:
        speed, angle = float(state["speed"]), float(state["angle"])

        def put() -> None:
            self.speed, self.angle = speed, angle

        return put

    def _rotor(self) -> tuple[float, float, float]:
        """(inertia, damping, torque held over the step) of the rotor now."""
        raise NotImplementedError(f"{type(self).__name__} must name its rotor")

    def _advance(self, h: float) -> Refusal | None:
        speed, increment = exact_rotor_step(self.speed, *self._rotor(), h)
        limit = bounds(self.table.BY_NAME["speed_start"])[1]
        if not abs(speed) <= limit:
            torque = self._TORQUE_INPUT
            details = {torque: getattr(self, torque), "step_size": h}
            return Refusal(self._SPEED_REASON, "speed", speed, limit, self.time, "rad/s", details)
        self.angle += increment
        self.speed = speed
        return None
