"""The Load FMU: a driven machine without state."""

from .. import Model, stepped
from .model import Load
from .variables import LOAD

MODEL = Model(
    key="Load",
    description="Driven machine: inertia, viscous drag and constant torque",
    table_for=lambda settings: LOAD,
    make=stepped(Load),
    owner="load",
)
