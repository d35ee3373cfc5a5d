"""`CompliantPropshaft`: the propshaft (`models.propshaft.model.Propshaft`, N joints in 3-D) with
the torsional spring-damper of `models.compliant_joint.model.CompliantDrive` at its output end: the
same layer, inputs, parameters and outputs as the `CompliantJoint`'s."""

from ..compliant_joint.model import CompliantDrive
from ..propshaft import Propshaft
from .variables import compliant_propshaft_table


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

    def _kinematics(self) -> tuple[float, float]:
        return self.rigid.kinematics()

    def warnings(self):
        """The rigid propshaft's angle checks (never refusals)."""
        return self.rigid.warnings()
