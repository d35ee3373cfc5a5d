"""The UniversalJoint FMU: one exact Cardan joint."""

from .. import Model, stepped
from . import variables
from .model import CardanJoint

MODEL = Model(
    key="UniversalJoint",
    description=(
        "Exact Cardan (Hooke) universal joint: output shaft motion, crosspiece "
        "orientation and dynamics, input torque and secondary couples"
    ),
    table_for=lambda settings: variables,
    make=stepped(CardanJoint),
    live_outputs=("input_angle",),
    owner="joint",
)
