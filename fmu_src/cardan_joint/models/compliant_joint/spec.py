"""The CompliantJoint FMU: the exact joint with a torsional spring-damper at its output."""

from .. import Model, stepped
from .model import CompliantJoint
from .variables import COMPLIANT_JOINT

MODEL = Model(
    key="CompliantJoint",
    description=(
        "Exact Cardan (Hooke) universal joint with a torsional spring-damper at its "
        "output: takes both shaft speeds, returns both torques"
    ),
    table_for=lambda settings: COMPLIANT_JOINT,
    make=stepped(CompliantJoint),
    live_outputs=("input_angle", "output_angle"),
    owner="joint",
)
