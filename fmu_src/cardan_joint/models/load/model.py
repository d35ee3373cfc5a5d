"""The Load as a stepped system: a driven machine with inertia, viscous drag and a
constant torque; it has no state: torque = J a + c omega + T0 of the shaft motion
it is given. The step is `step.load_step`, which the FMU's C runtime is
generated from."""

from ...framework.refusal import Refusal
from ...framework.written_step import WrittenStep
from .step import load_step, load_torque
from .variables import LOAD


class Load(WrittenStep):
    table = LOAD

    # `LOAD`'s inputs and parameters, set by __init__.
    speed: float
    acceleration: float
    inertia: float
    drag: float
    constant_torque: float

    def written_step(self):
        return load_step

    def step_state(self) -> tuple:
        """(whether the parameters let the load run,): `step.STATE`."""
        return (self.parameter_fault is None,)

    def set_step_state(self, state) -> None:
        pass  # the parameters' verdict is fixed at `start`: nothing moves

    def _advance(self, h: float) -> Refusal | None:
        return None  # no state: the torque follows the shaft motion it is given

    def outputs(self) -> tuple:
        """Values of `LOAD.OUTPUTS`: torque = J a + c omega + T0."""
        return (
            load_torque(
                self.speed, self.acceleration, self.inertia, self.drag, self.constant_torque
            ),
        )
