"""The Motor as a stepped system: a rotor of inertia J driven by the linear
characteristic T(omega) = T_s (1 - omega / omega_0) (stall torque T_s, no-load
speed omega_0) against a load torque T_L held over the step. With k = T_s / omega_0
the rotor obeys J d(omega)/dt = T_s - k omega - T_L, a linear ODE solved exactly
over a step (`physics.stepped.exact_rotor_step`): no integration error at any step.
"""

from ...physics.refusal import Refusal
from ...physics.stepped import _TableModel, exact_rotor_step
from ...physics.values import bounds
from .refusals import MotorReason
from .variables import MOTOR


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
                MotorReason.ROTOR_SPEED,
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
