"""The InertiaLoad FMU's slave: the joint's FMI 2 slave (every FMI rule, state and
refusal, see `core`) mapped onto `physics.inertia_load` and its table. Its speed
and angle are its state; only the acceleration depends on the input."""

from ..inertia_load_variables import INERTIA_LOAD
from ..physics.inertia_load import InertiaLoad
from .slave import CardanJointSlave


class InertiaLoadSlave(CardanJointSlave):
    description = (
        "Driven machine with inertia, viscous drag and constant torque, "
        "integrated exactly over each step with the drive torque held"
    )
    table = INERTIA_LOAD
    live_outputs = ()
    owner = "load"

    def _new_model(self):
        return InertiaLoad(**self.start_overrides)
