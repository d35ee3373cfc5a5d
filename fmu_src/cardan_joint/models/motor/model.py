"""The Motor as a stepped system: a rotor of inertia J driven by the linear
characteristic T(omega) = T_s (1 - omega / omega_0) (stall torque T_s, no-load
speed omega_0) against a load torque T_L held over the step. With k = T_s / omega_0
the rotor obeys J d(omega)/dt = T_s - k omega - T_L, a linear ODE solved exactly
over a step (`physics.rotor.exact_rotor_step`): no integration error at any step.
The step is `step.motor_step`, which the FMU's C runtime is generated from.
"""

from ...framework.rotor_model import RotorModel
from .refusals import MotorReason
from .step import motor_outputs, motor_rotor, motor_step, motor_torque
from .variables import MOTOR


class Motor(RotorModel):
    table = MOTOR
    _SPEED_REASON = MotorReason.ROTOR_SPEED
    _TORQUE_INPUT = "load_torque"

    # `MOTOR`'s input and parameters (set by __init__); the rotor's state is the base's.
    load_torque: float
    stall_torque: float
    no_load_speed: float
    rotor_inertia: float
    speed_start: float
    angle_start: float

    @property
    def drag_constant(self) -> float:
        """k = T_s / omega_0, the characteristic's slope (N.m.s/rad)."""
        return self._rotor()[1]

    def torque(self, speed: float) -> float:
        return motor_torque(speed, self.stall_torque, self.no_load_speed)

    def equilibrium_speed(self) -> float:
        """Speed at which the motor torque balances the load torque."""
        return self.no_load_speed * (1.0 - self.load_torque / self.stall_torque)

    def time_constant(self) -> float:
        return self.rotor_inertia / self.drag_constant

    def written_step(self):
        return motor_step

    def _rotor(self) -> tuple[float, float, float]:
        return motor_rotor(
            self.load_torque, self.stall_torque, self.no_load_speed, self.rotor_inertia
        )

    def outputs(self) -> tuple:
        """Values of `MOTOR.OUTPUTS`: speed, acceleration, angle, motor torque."""
        return motor_outputs(
            self.speed, self.angle, self.load_torque, self.stall_torque, self.no_load_speed,
            self.rotor_inertia,
        )  # fmt: skip
