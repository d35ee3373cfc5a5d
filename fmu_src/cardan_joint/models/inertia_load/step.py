"""The InertiaLoad's step, written once: the definition `InertiaLoad.run` runs
and the build translates into the FMU's C runtime (docs/codegen.md), so both
give the same bits. Pure functions of floats: the load's speed and angle (the
state), the drive torque held over the step and the load's parameters."""

from ...framework.rotor_model import ROTOR_STATE, rotor_moved, rotor_speed_limit
from ...framework.values import bounds
from ...framework.written_step import sound_step
from .variables import INERTIA_LOAD

STATE = ROTOR_STATE
SPEED_LIMIT = rotor_speed_limit(INERTIA_LOAD)
DRIVE_LOW, DRIVE_HIGH = bounds(INERTIA_LOAD.BY_NAME["drive_torque"])


def load_rotor(
    drive_torque: float, inertia: float, drag: float, constant_torque: float
) -> tuple[float, float, float]:
    """(J, c, T - T0): J omega' = T - T0 - c omega, the Motor's rotor equation."""
    return inertia, drag, drive_torque - constant_torque


def load_outputs(
    speed: float,
    angle: float,
    drive_torque: float,
    inertia: float,
    drag: float,
    constant_torque: float,
) -> tuple[float, float, float]:
    """The outputs in the table's order: speed, acceleration, angle."""
    acceleration = (drive_torque - constant_torque - drag * speed) / inertia
    return speed, acceleration, angle


def inertia_load_step(
    time: float,
    h: float,
    speed: float,
    angle: float,
    parameters_valid: bool,
    drive_torque: float,
    inertia: float,
    drag: float,
    constant_torque: float,
    speed_start: float,
    angle_start: float,
) -> tuple | None:
    """A step of `h` s from `time`: the state (`STATE`), the drive torque and the
    outputs, or None when the step is not taken here (a NaN, a value out of its
    range, a speed past the limit): the model's checks then name the refusal.
    The start values enter through the state (`start`), not as parameters."""
    if not (sound_step(h, parameters_valid) and DRIVE_LOW <= drive_torque <= DRIVE_HIGH):
        return None
    rotor = load_rotor(drive_torque, inertia, drag, constant_torque)
    end_speed, end_angle, within = rotor_moved(h, speed, angle, *rotor, SPEED_LIMIT)
    if not within:
        return None
    outputs = load_outputs(end_speed, end_angle, drive_torque, inertia, drag, constant_torque)
    return (end_speed, end_angle, parameters_valid, drive_torque) + outputs
