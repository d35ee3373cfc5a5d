"""The Motor's step, written once: the definition `Motor.run` runs and the build
translates into the FMU's C runtime (docs/codegen.md), so both give the same
bits. Pure functions of floats: the rotor's speed and angle (the state), the
load torque held over the step and the motor's parameters."""

from ...framework.rotor_model import ROTOR_STATE, rotor_entry
from .variables import MOTOR

STATE = ROTOR_STATE


def motor_torque(speed: float, stall_torque: float, no_load_speed: float) -> float:
    """T(omega) = T_s (1 - omega / omega_0), the linear characteristic."""
    return stall_torque * (1.0 - speed / no_load_speed)


def motor_rotor(
    load_torque: float, stall_torque: float, no_load_speed: float, rotor_inertia: float
) -> tuple[float, float, float]:
    """(J, k = T_s / omega_0, T_s - T_L): J omega' = T_s - T_L - k omega."""
    return rotor_inertia, stall_torque / no_load_speed, stall_torque - load_torque


def motor_outputs(
    speed: float,
    angle: float,
    load_torque: float,
    stall_torque: float,
    no_load_speed: float,
    rotor_inertia: float,
) -> tuple[float, float, float, float]:
    """The outputs in the table's order: speed, acceleration, angle, motor torque."""
    torque = motor_torque(speed, stall_torque, no_load_speed)
    return speed, (torque - load_torque) / rotor_inertia, angle, torque


# The step (the spec's `step`): the rotor's, driven by the load torque.
motor_step = rotor_entry("motor_step", MOTOR, "load_torque", motor_rotor, motor_outputs)
