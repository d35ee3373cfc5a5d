"""The Load's step, written once: the definition `Load.run` runs and the build
translates into the FMU's C runtime (docs/codegen.md), so both give the same
bits. The Load has no state of its own: its torque follows the shaft motion it
is given; the step state is only whether the parameters let it run."""

from ...framework.values import bounds
from ...framework.written_step import sound_step
from .variables import LOAD

STATE = ("parameters_valid",)
SPEED_LOW, SPEED_HIGH = bounds(LOAD.BY_NAME["speed"])
ACCELERATION_LOW, ACCELERATION_HIGH = bounds(LOAD.BY_NAME["acceleration"])


def load_torque(
    speed: float, acceleration: float, inertia: float, drag: float, constant_torque: float
) -> float:
    """The torque the load takes: J a + c omega + T0."""
    return inertia * acceleration + drag * speed + constant_torque


def load_step(
    time: float,
    h: float,
    parameters_valid: bool,
    speed: float,
    acceleration: float,
    inertia: float,
    drag: float,
    constant_torque: float,
) -> tuple | None:
    """A step of `h` s from `time`: the state (`STATE`), the inputs as given and
    the torque, or None when the step is not taken here (a NaN, a value out of
    its range): the model's checks then name the refusal."""
    if not (
        sound_step(h, parameters_valid)
        and SPEED_LOW <= speed <= SPEED_HIGH
        and ACCELERATION_LOW <= acceleration <= ACCELERATION_HIGH
    ):
        return None
    torque = load_torque(speed, acceleration, inertia, drag, constant_torque)
    return parameters_valid, speed, acceleration, torque
