"""The Propshaft FMU's slave: the joint's slave (every FMI rule, state and
refusal) mapped onto `physics.propshaft.Propshaft` and the Propshaft's table."""

from ..physics.propshaft import Propshaft
from ..propshaft_variables import propshaft_table
from .slave import CardanJointSlave


class PropshaftSlave(CardanJointSlave):
    description = (
        "Propshaft of several exact Cardan joints in 3-D: working angles from "
        "side and top views, yoke phasing, intermediate shaft inertia, input "
        "torque, speed-ratio fluctuation and the joint makers' angle checks"
    )
    # Written in by the build script: {"joints": N}.
    build_settings: dict = {}
    table = propshaft_table(2)

    joints = 2

    def __init_subclass__(cls, **kwargs):
        cls.joints = int(cls.build_settings.get("joints", 2))
        cls.table = cls._table_for(cls.joints)
        super().__init_subclass__(**kwargs)

    @staticmethod
    def _table_for(joints: int):
        """The table of the model built for `joints` joints."""
        return propshaft_table(joints)

    def _new_model(self):
        return Propshaft(self.joints, **self.start_overrides)

    def _initialization_warnings(self):
        return self._model.warnings()
