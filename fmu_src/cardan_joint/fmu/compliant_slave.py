"""The CompliantJoint FMU's slave: the joint's FMI 2 slave (every FMI rule, state
and refusal, see `core`) mapped onto `physics.compliant` and its table. The
input and output angles follow the state while an input is invalid; every
other output that depends on an invalid input is held."""

from ..compliant_variables import COMPLIANT_JOINT
from ..physics.compliant import CompliantJoint
from .slave import CardanJointSlave


class CompliantJointSlave(CardanJointSlave):
    description = (
        "Exact Cardan (Hooke) universal joint with a torsional spring-damper at its "
        "output: takes both shaft speeds, returns both torques"
    )
    table = COMPLIANT_JOINT
    live_outputs = ("input_angle", "output_angle")

    def _new_model(self):
        return CompliantJoint(**self.start_overrides)
