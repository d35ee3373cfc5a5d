"""The Load FMU: a driven machine without state."""

from .. import Model, ReferenceRun, stepped
from .model import Load
from .step import load_step
from .variables import LOAD

MODEL = Model(
    key="Load",
    description="Driven machine: inertia, viscous drag and constant torque",
    table_for=lambda settings: LOAD,
    make=stepped(Load),
    owner="load",
    step=lambda settings: load_step,  # the step in C (docs/codegen.md)
    # The shaft runs up at a constant 10 rad/s2 from rest: the torque grows from
    # the constant torque and the inertia's share by the drag's.
    reference=ReferenceRun(
        input_rows=((0.0, 0.0, 10.0), (1.0, 10.0, 10.0)),  # time, speed, acceleration
        outputs=("torque",),
    ),
)
