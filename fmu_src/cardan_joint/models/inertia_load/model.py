"""`InertiaLoad`: a driven machine with inertia, as a stepped system.

J d(omega)/dt = drive_torque - drag omega - constant_torque, the drive torque held
over a step: the Motor's linear rotor equation, solved exactly by the same
`driveline.exact_rotor_step` (drag = 0 included). The constant torque is a
torque, not a friction: at standstill it turns the load backwards unless the
drive torque balances it. Same protocol and checks as the Motor.
"""

from ...physics.refusal import Refusal
from ...physics.stepped import _TableModel, exact_rotor_step
from ...physics.values import bounds
from .refusals import InertiaLoadReason
from .variables import INERTIA_LOAD


class InertiaLoad(_TableModel):
    table = INERTIA_LOAD
    _SPEED_LIMIT = bounds(INERTIA_LOAD.BY_NAME["speed_start"])[1]

    # `INERTIA_LOAD`'s input and parameters (set by __init__), then the state.
    drive_torque: float
    inertia: float
    drag: float
    constant_torque: float
    speed_start: float
    angle_start: float
    speed: float
    angle: float

    def start(self, time: float) -> None:
        super().start(time)
        valid = not self.parameter_fault
        self.speed = self.speed_start if valid else 0.0
        self.angle = self.angle_start if valid else 0.0

    def _net_torque(self) -> float:
        return self.drive_torque - self.constant_torque

    def _advance(self, h: float) -> Refusal | None:
        speed, increment = exact_rotor_step(
            self.speed, self.inertia, self.drag, self._net_torque(), h
        )
        if not abs(speed) <= self._SPEED_LIMIT:
            return Refusal(
                InertiaLoadReason.LOAD_SPEED,
                "speed",
                speed,
                self._SPEED_LIMIT,
                self.time,
                "rad/s",
                {"drive_torque": self.drive_torque, "step_size": h},
            )
        self.angle += increment
        self.speed = speed
        return None

    def outputs(self) -> tuple:
        """Values of `INERTIA_LOAD.OUTPUTS`: speed, acceleration, angle."""
        acceleration = (self._net_torque() - self.drag * self.speed) / self.inertia
        return (self.speed, acceleration, self.angle)

    def _variables(self) -> tuple[str, ...]:
        return super()._variables() + ("speed", "angle")
