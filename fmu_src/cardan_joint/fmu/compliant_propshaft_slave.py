"""The CompliantPropshaft FMU's slave: the Propshaft's slave (N joints, the angle
checks as warnings) mapped onto `physics.compliant_propshaft` and its table."""

from ..compliant_variables import compliant_propshaft_table
from ..physics.compliant_propshaft import CompliantPropshaft
from .propshaft_slave import PropshaftSlave


class CompliantPropshaftSlave(PropshaftSlave):
    description = (
        "Propshaft of several exact Cardan joints in 3-D with a torsional "
        "spring-damper at its output: takes both shaft speeds, returns both torques"
    )
    table = compliant_propshaft_table(2)
    live_outputs = ("input_angle", "output_angle")

    @staticmethod
    def _table_for(joints: int):
        return compliant_propshaft_table(joints)

    def _new_model(self):
        return CompliantPropshaft(self.joints, **self.start_overrides)
