"""The Motor's step, written once: the definition `Motor.run` runs and the build
translates into the FMU's C runtime (docs/codegen.md), so both give the same
bits. Pure functions of floats: the rotor's speed and angle (the state), the
load torque held over the step and the motor's parameters."""

from ...framework.rotor_model import ROTOR_STATE, rotor_moved, rotor_speed_limit
from ...framework.values import bounds
from ...framework.written_step import sound_step
from .variables import MOTOR

STATE = ROTOR_STATE
SPEED_LIMIT = rotor_speed_limit(MOTOR)
LOAD_LOW, LOAD_HIGH = bounds(MOTOR.BY_NAME["load_torque"])


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


def motor_step(
    time: float,
    h: float,
    speed: float,
    angle: float,
    parameters_valid: bool,
    load_torque: float,
    stall_torque: float,
    no_load_speed: float,
    rotor_inertia: float,
    speed_start: float,
    angle_start: float,
) -> tuple | None:
    """A step of `h` s from `time`: the state (`STATE`), the load torque and the
    outputs, or None when the step is not taken here (a NaN, a value out of its
    range, a speed past the limit): the model's checks then name the refusal.
    The start values enter through the state (`start`), not as parameters."""
    if not (sound_step(h, parameters_valid) and LOAD_LOW <= load_torque <= LOAD_HIGH):
        return None
    rotor = motor_rotor(load_torque, stall_torque, no_load_speed, rotor_inertia)
    end_speed, end_angle, within = rotor_moved(h, speed, angle, *rotor, SPEED_LIMIT)
    if not within:
        return None
    outputs = motor_outputs(
        end_speed, end_angle, load_torque, stall_torque, no_load_speed, rotor_inertia
    )
    return (end_speed, end_angle, parameters_valid, load_torque) + outputs
