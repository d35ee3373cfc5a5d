"""pythonfmu script of the Motor FMU (see `UniversalJoint.py` for how the build ships it)."""

import ctypes

from cardan_joint.fmu.component import ComponentSlave
from cardan_joint.physics.driveline import Motor as _Physics

# pythonfmu 0.7.0 releases one reference too many to this namespace at every
# fmi2Instantiate (see UniversalJoint.py); one reference per run keeps the count right.
ctypes.pythonapi.Py_IncRef(ctypes.py_object(globals()))


class Motor(ComponentSlave):
    description = ("Motor with a linear torque-speed characteristic and rotor inertia, "
                   "integrated exactly over each step")
    model_class = _Physics
    start_overrides = {}
