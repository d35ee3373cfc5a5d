"""What the models stepped from a variable table share: `_TableModel` (inputs and
parameters as attributes with the table's start values, their checks, the step
and the state) and the exact rotor step of a driven inertia.

Every stepped model follows `CardanJoint`'s protocol (start, step returning a
`Refusal` or None, outputs in table order, parameter_fault, input_problem,
invalid_inputs, state/restore), which the FMU slaves' core relies on; the value
and step-size checks are the joint's (`values.ValueChecks`).
"""

import math

from ..variable_schema import VariableTable
from .refusal import Refusal
from .values import ValueChecks, set_start_values, value_ranges


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


class _TableModel(ValueChecks):
    """Inputs and parameters as attributes with the table's start values; the checks."""

    table: VariableTable

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
        return {r.variable for r in self._bad_values(self.table.INPUTS, self._input_ranges)}

    def step(self, step_size: float) -> Refusal | None:
        """Advance by `step_size`; return None, or the Refusal of the step (then
        nothing has changed, the clock neither)."""
        problem = self.step_problem(step_size) or self._advance(step_size)
        if problem:
            return problem
        self.time += step_size
        return None

    def _advance(self, h: float) -> Refusal | None:
        """Move the state `h` s on, or refuse (then nothing has changed)."""
        raise NotImplementedError(f"{type(self).__name__} must advance its state")

    def _variables(self) -> tuple[str, ...]:
        return self.table.INPUTS + self.table.PARAMETERS

    def state(self) -> dict:
        values = {name: getattr(self, name) for name in self._variables()}
        values["time"] = self.time
        return values

    def restore(self, state: dict) -> None:
        """Take a `state()`; all or nothing (a malformed state raises and changes nothing)."""
        values = {name: float(state[name]) for name in self._variables()}
        values["time"] = float(state["time"])
        for name, value in values.items():
            setattr(self, name, value)
        self.parameter_fault = self.parameter_problem()
