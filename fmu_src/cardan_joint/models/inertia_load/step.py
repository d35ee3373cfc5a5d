"""The InertiaLoad's step, written once: the definition `InertiaLoad.run` runs
and the build translates into the FMU's C runtime (docs/codegen.md), so both
give the same bits. Pure functions of floats: the load's speed and angle (the
state), the drive torque held over the step and the load's parameters."""

from ...framework.rotor_model import ROTOR_STATE, rotor_entry
from .variables import INERTIA_LOAD

STATE = ROTOR_STATE


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


# The step (the spec's `step`): the rotor's, driven by the drive torque.
inertia_load_step = rotor_entry(
    "inertia_load_step", INERTIA_LOAD, "drive_torque", load_rotor, load_outputs
)
