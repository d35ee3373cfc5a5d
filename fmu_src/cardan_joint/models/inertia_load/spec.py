"""The InertiaLoad FMU: a driven machine whose speed and angle are its state."""

from .. import Model, ReferenceRun, stepped
from .model import InertiaLoad
from .step import inertia_load_step
from .variables import INERTIA_LOAD

MODEL = Model(
    key="InertiaLoad",
    description=(
        "Driven machine with inertia, viscous drag and constant torque, "
        "integrated exactly over each step with the drive torque held"
    ),
    table_for=lambda settings: INERTIA_LOAD,
    make=stepped(InertiaLoad),
    owner="load",
    step=lambda settings: inertia_load_step,  # the step in C (docs/codegen.md)
    # The drive torque ramps through the constant torque (20 N.m): the load
    # first turns backwards, then runs up.
    reference=ReferenceRun(
        input_rows=((0.0, 0.0), (1.0, 60.0)),  # time, drive_torque
        outputs=("speed", "acceleration", "angle"),
    ),
)
