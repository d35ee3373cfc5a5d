"""The driveline's end pieces as stepped systems: a `Motor` and a `Load`.

`Motor`: a rotor of inertia J driven by the linear characteristic
T(omega) = T_s (1 - omega / omega_0) (stall torque T_s, no-load speed omega_0)
against a load torque T_L held over the step. With k = T_s / omega_0 the rotor obeys
J d(omega)/dt = T_s - k omega - T_L, a linear ODE solved exactly over a step:
omega(t) = omega_eq + (omega(0) - omega_eq) exp(-t / tau), omega_eq = (T_s - T_L) / k,
tau = J / k, and the angle is its exact integral. No integration error at any step.

`Load`: a driven machine with inertia, viscous drag and a constant torque; it
has no state: torque = J a + c omega + T0 of the shaft motion it is given.

Both follow `CardanJoint`'s protocol (start, step returning a `Refusal` or None,
outputs in table order, parameter_fault, input_problem, invalid_inputs,
state/restore), which the FMU slaves' core relies on; the value and step-size
checks are the joint's (`values.ValueChecks`).
"""

import math

from ..driveline_variables import LOAD, MOTOR
from ..variable_schema import VariableTable
from .refusal import Reason, Refusal
from .values import ValueChecks, bounds, set_start_values, value_ranges


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


class Motor(_TableModel):
    table = MOTOR
    _SPEED_LIMIT = bounds(MOTOR.BY_NAME["speed_start"])[1]

    # `MOTOR`'s input and parameters (set by __init__), then the rotor's state.
    load_torque: float
    stall_torque: float
    no_load_speed: float
    rotor_inertia: float
    speed_start: float
    angle_start: float
    speed: float
    angle: float

    def start(self, time: float) -> None:
        super().start(time)
        valid = not self.parameter_fault
        self.speed = self.speed_start if valid else 0.0
        self.angle = self.angle_start if valid else 0.0

    @property
    def drag_constant(self) -> float:
        """k = T_s / omega_0, the characteristic's slope (N.m.s/rad)."""
        return self.stall_torque / self.no_load_speed

    def torque(self, speed: float) -> float:
        return self.stall_torque * (1.0 - speed / self.no_load_speed)

    def equilibrium_speed(self) -> float:
        """Speed at which the motor torque balances the load torque."""
        return self.no_load_speed * (1.0 - self.load_torque / self.stall_torque)

    def time_constant(self) -> float:
        return self.rotor_inertia / self.drag_constant

    def _advance(self, h: float) -> Refusal | None:
        speed, increment = exact_rotor_step(
            self.speed,
            self.rotor_inertia,
            self.drag_constant,
            self.stall_torque - self.load_torque,
            h,
        )
        if not abs(speed) <= self._SPEED_LIMIT:
            return Refusal(
                Reason.ROTOR_SPEED,
                "speed",
                speed,
                self._SPEED_LIMIT,
                self.time,
                "rad/s",
                {"load_torque": self.load_torque, "step_size": h},
            )
        self.angle += increment
        self.speed = speed
        return None

    def outputs(self) -> tuple:
        """Values of `MOTOR.OUTPUTS`: speed, acceleration, angle, motor torque."""
        torque = self.torque(self.speed)
        return (self.speed, (torque - self.load_torque) / self.rotor_inertia, self.angle, torque)

    def _variables(self) -> tuple[str, ...]:
        return super()._variables() + ("speed", "angle")


class Load(_TableModel):
    table = LOAD

    # `LOAD`'s inputs and parameters, set by __init__.
    speed: float
    acceleration: float
    inertia: float
    drag: float
    constant_torque: float

    def _advance(self, h: float) -> Refusal | None:
        return None  # no state: the torque follows the shaft motion it is given

    def outputs(self) -> tuple:
        """Values of `LOAD.OUTPUTS`: torque = J a + c omega + T0."""
        return (self.inertia * self.acceleration + self.drag * self.speed + self.constant_torque,)
