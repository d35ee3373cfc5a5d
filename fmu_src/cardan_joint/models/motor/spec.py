"""The Motor FMU: a rotor driven by a linear torque-speed characteristic."""

from .. import Model, stepped
from .model import Motor
from .step import motor_step
from .variables import MOTOR

MODEL = Model(
    key="Motor",
    description=(
        "Motor with a linear torque-speed characteristic and rotor inertia, "
        "integrated exactly over each step"
    ),
    table_for=lambda settings: MOTOR,
    make=stepped(Motor),
    owner="motor",
    step=lambda settings: motor_step,  # the step in C (docs/codegen.md)
)
