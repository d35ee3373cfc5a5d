"""A stepped model whose state is one rotor (the motor, the inertia load): speed
and angle from their start parameters, advanced by the exact rotor step
(`physics.rotor`), a speed beyond `speed_start`'s range refused. Its step is
written once, `rotor_step` with the model's own rotor and outputs (its
folder's `step.py`, `rotor_entry`), and moves the rotor by `rotor_moved`,
which the checks' path (`_advance`) takes too."""

from collections.abc import Callable
from typing import Any

from ..physics.rotor import exact_rotor_step
from .grouped_entry import Group, GroupedEntry
from .refusal import Refusal
from .values import bounds
from .written_step import WrittenStep, grouped_step, sound_step

# The step state of a rotor's written step, in its parameters' order.
ROTOR_STATE = ("speed", "angle", "parameters_valid")


def rotor_speed_limit(table) -> float:
    """The rotor's speed limit: the bound of its `speed_start` parameter's range."""
    return bounds(table.BY_NAME["speed_start"])[1]


def rotor_moved(
    h: float,
    speed: float,
    angle: float,
    inertia: float,
    damping: float,
    torque: float,
    speed_limit: float,
) -> tuple[float, float, bool]:
    """The rotor after `h` s of J w' = torque - damping w, the torque held: its
    speed and angle, and whether the speed stays within `speed_limit` (if not,
    the step is refused and the rotor stays)."""
    end_speed, increment = exact_rotor_step(speed, inertia, damping, torque, h)
    return end_speed, angle + increment, abs(end_speed) <= speed_limit


def rotor_step(time, h, speed, angle, parameters_valid: bool, torque, parameters, starts,
               torque_low, torque_high, speed_limit, rotor_of,
               outputs_of) -> tuple | None:  # fmt: skip
    """A step of `h` s from `time` of a rotor driven by `torque`, held over the
    step: the state (`ROTOR_STATE`), the torque and the outputs
    (`outputs_of(speed, angle, torque, *parameters)`), or None when the step
    is not taken here (a NaN, a value out of its range, a speed past the
    limit): the model's checks then name the refusal. `rotor_of(torque,
    *parameters)` gives its equation's (inertia, damping, torque). The start
    values enter through the state (`start`), not as parameters."""
    if not (sound_step(h, parameters_valid) and torque_low <= torque <= torque_high):
        return None
    inertia, damping, drive = rotor_of(torque, *parameters)
    end_speed, end_angle, within = rotor_moved(h, speed, angle, inertia, damping, drive,
                                               speed_limit)  # fmt: skip
    if not within:
        return None
    outputs = outputs_of(end_speed, end_angle, torque, *parameters)
    return (end_speed, end_angle, parameters_valid, torque) + outputs


def rotor_entry(name: str, table, torque: str, rotor_of: Callable, outputs_of: Callable
                ) -> GroupedEntry:  # fmt: skip
    """The step entry `name` of the rotor model of `table`, whose input `torque`
    drives it (`rotor_step`): its parameters before the start values are
    `rotor_of`'s and `outputs_of`'s; the limits are the table's ranges."""
    low, high = bounds(table.BY_NAME[torque])
    starts = ("speed_start", "angle_start")
    groups: dict[str, Group] = {"torque": torque, "starts": starts,
              "parameters": tuple(n for n in table.PARAMETERS if n not in starts)}  # fmt: skip
    bound = {"torque_low": low, "torque_high": high, "speed_limit": rotor_speed_limit(table),
             "rotor_of": rotor_of, "outputs_of": outputs_of}  # fmt: skip
    return grouped_step(name, rotor_step, ROTOR_STATE, table, groups, bound)


class RotorModel(WrittenStep):
    """The rotor's state, its saved state and its step's refusal of a speed out
    of range (`_SPEED_REASON`, naming the torque input `_TORQUE_INPUT`)."""

    _SPEED_REASON: Any
    _TORQUE_INPUT: str
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

    def step_state(self) -> tuple:
        """(speed, angle, whether the parameters let the rotor run): `ROTOR_STATE`."""
        return self.speed, self.angle, self.parameter_fault is None

    def set_step_state(self, state) -> None:
        # The parameters' verdict is fixed at `start`: only the rotor moves.
        self.speed, self.angle = float(state[0]), float(state[1])

    def _rotor(self) -> tuple[float, float, float]:
        """(inertia, damping, torque held over the step) of the rotor now."""
        raise NotImplementedError(f"{type(self).__name__} must name its rotor")

    def _advance(self, h: float) -> Refusal | None:
        limit = rotor_speed_limit(self.table)
        speed, angle, within = rotor_moved(h, self.speed, self.angle, *self._rotor(), limit)
        if not within:
            torque = self._TORQUE_INPUT
            details = {torque: getattr(self, torque), "step_size": h}
            return Refusal(self._SPEED_REASON, "speed", speed, limit, self.time, "rad/s", details)
        self.speed, self.angle = speed, angle
        return None
