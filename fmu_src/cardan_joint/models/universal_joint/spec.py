"""The UniversalJoint FMU: one exact Cardan joint."""

from .. import Model
from . import variables
from .model import CardanJoint

MODEL = Model(
    key="UniversalJoint",
    description=(
        "Exact Cardan (Hooke) universal joint: output shaft motion, crosspiece "
        "orientation and dynamics, input torque and secondary couples"
    ),
    table_for=lambda settings: variables.table_for(settings.get("life", True)),
    make=lambda settings, **values: CardanJoint(settings.get("life", True), **values),
    live_outputs=("input_angle",),
    owner="joint",
    # `life`: the bearing loads and catalogue life (docs/life.md); off measures
    # the joint's step without them.
    default_settings={"life": True},
    name_for=lambda settings: (
        "UniversalJoint" if settings.get("life", True) else ("UniversalJointNoLife")
    ),
)
