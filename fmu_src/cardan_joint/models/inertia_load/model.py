"""`InertiaLoad`: a driven machine with inertia, as a stepped system.

J d(omega)/dt = drive_torque - drag omega - constant_torque, the drive torque held
over a step: the Motor's linear rotor equation, solved exactly by the same
`physics.rotor.exact_rotor_step` (drag = 0 included). The constant torque is a
torque, not a friction: at standstill it turns the load backwards unless the
drive torque balances it. Same protocol and checks as the Motor; the step is
`step.inertia_load_step`, which the FMU's C runtime is generated from.
"""

from ...framework.rotor_model import RotorModel
from .refusals import InertiaLoadReason
from .step import inertia_load_step, load_outputs, load_rotor
from .variables import INERTIA_LOAD


class InertiaLoad(RotorModel):
    table = INERTIA_LOAD
    _SPEED_REASON = InertiaLoadReason.LOAD_SPEED
    _TORQUE_INPUT = "drive_torque"

    # `INERTIA_LOAD`'s input and parameters (set by __init__); the state is the base's.
    drive_torque: float
    inertia: float
    drag: float
    constant_torque: float
    speed_start: float
    angle_start: float

    def written_step(self):
        return inertia_load_step

    def _rotor(self) -> tuple[float, float, float]:
        return load_rotor(self.drive_torque, self.inertia, self.drag, self.constant_torque)

    def outputs(self) -> tuple:
        """Values of `INERTIA_LOAD.OUTPUTS`: speed, acceleration, angle."""
        return load_outputs(
            self.speed, self.angle, self.drive_torque, self.inertia, self.drag,
            self.constant_torque,
        )  # fmt: skip
