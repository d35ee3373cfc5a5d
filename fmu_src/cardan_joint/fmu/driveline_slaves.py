"""The Motor and Load FMUs' slaves: the joint's FMI 2 slave (every FMI rule,
state and refusal, see `core`) mapped onto `physics.driveline` and its tables.

Neither has an output that follows its state while an input is invalid (the
joint's input angle): every output that depends on an invalid input is held at
its last valid value, the others follow the model, as their dependencies say."""

from ..driveline_variables import LOAD, MOTOR
from ..physics.driveline import Load, Motor
from .slave import CardanJointSlave


class MotorSlave(CardanJointSlave):
    description = (
        "Motor with a linear torque-speed characteristic and rotor inertia, "
        "integrated exactly over each step"
    )
    table = MOTOR
    live_outputs = ()
    owner = "motor"

    def _new_model(self):
        return Motor(**self.start_overrides)


class LoadSlave(CardanJointSlave):
    description = "Driven machine: inertia, viscous drag and constant torque"
    table = LOAD
    live_outputs = ()
    owner = "load"

    def _new_model(self):
        return Load(**self.start_overrides)
