"""`CompliantPropshaft`: the propshaft (`models.propshaft.model.Propshaft`, N joints in 3-D) with
the torsional spring-damper of `models.compliant_joint.model.CompliantDrive` at its output end: the
same layer, inputs, parameters and outputs as the `CompliantJoint`'s."""

from ..compliant_joint.model import CompliantDrive
from ..propshaft import Propshaft
from ..propshaft.step import state_names
from .entries import STEPS
from .step import spring_chain_torque
from .variables import compliant_propshaft_table

_VALID = state_names(2).index("parameters_valid")


class CompliantPropshaft(CompliantDrive):
    # The rigid propshaft's inputs and parameters every layout has, kept in `rigid`
    # (see CompliantDrive); the per-shaft ones are read by name.
    input_speed: float
    input_acceleration: float
    input_angle_start: float
    crosspiece_inertia_1: float
    crosspiece_inertia_2: float
    crosspiece_inertia_3: float
    max_working_angle: float
    bearing_radius: float
    rated_torque: float
    life_constant: float
    life_exponent: float
    life_min_angle: float

    def __init__(self, joints: int = 2, **values: float) -> None:
        table = compliant_propshaft_table(joints)
        super().__init__(Propshaft(joints), table, "compliant propshaft", **values)
        self.joints = joints

    def _written_step(self, time: float, h: float, state: tuple, inputs) -> tuple | None:
        """`step.compliant_propshaft_<N>_step`, with life on (without, the
        checked step in Python)."""
        if not self.rigid.life:
            return None
        return STEPS[self.joints](time, h, *state, *inputs)

    def step_state(self) -> tuple:
        """The values of `step.compliant_state_names`: the rigid propshaft's, with
        this drive's parameters' validity, then the lag, k and c."""
        rigid = self.rigid.step_state()
        valid = self.parameter_fault is None
        return (*rigid[:_VALID], valid, *rigid[_VALID + 1 :], self._lag,
                self.torsional_stiffness, self.torsional_damping)  # fmt: skip

    def set_step_state(self, state) -> None:
        """Take a state a generated step advanced (`step_state`'s values)."""
        rigid = len(state_names(self.joints))
        self.rigid.set_step_state(state[:rigid])
        self._lag = float(state[rigid])

    def _spring_over_step(self, speed: float, acceleration: float) -> tuple:
        """The chain's life under the spring, as the generated step takes it:
        `step.spring_chain_torque` from the spring's start."""
        shift = self.rigid._shifts[-1]
        spring = (shift, self._lag, speed, acceleration, self.torsional_stiffness,
                  self.torsional_damping)  # fmt: skip
        return spring_chain_torque, spring

    def _kinematics(self) -> tuple[float, float]:
        return self.rigid.kinematics()

    def warnings(self):
        """The rigid propshaft's angle checks (never refusals)."""
        return self.rigid.warnings()
