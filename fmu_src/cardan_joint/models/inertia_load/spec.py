"""The InertiaLoad FMU: a driven machine whose speed and angle are its state."""

from .. import Model, stepped
from .model import InertiaLoad
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
)
