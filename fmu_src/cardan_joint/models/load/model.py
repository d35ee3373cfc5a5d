"""The Load as a stepped system: a driven machine with inertia, viscous drag and a
constant torque; it has no state: torque = J a + c omega + T0 of the shaft motion
it is given."""

from ...framework.refusal import Refusal
from ...framework.stepped import SteppedModel
from .variables import LOAD


class Load(SteppedModel):
    table = LOAD

    # `LOAD`'s inputs and parameters, set by __init__.
    speed: float
    acceleration: float
    inertia: float
    drag: float
    constant_torque: float

    def _advance(self, h: float) -> Refusal | None:
        return None  # no state: the torque follows the shaft motion it is given

    def outputs(self) -> tuple:
        """Values of `LOAD.OUTPUTS`: torque = J a + c omega + T0."""
        return (self.inertia * self.acceleration + self.drag * self.speed + self.constant_torque,)
