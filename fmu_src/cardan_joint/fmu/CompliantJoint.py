"""pythonfmu script of the CompliantJoint FMU (see `UniversalJoint.py` for the build)."""

import ctypes

from cardan_joint.fmu.compliant_slave import CompliantJointSlave

# pythonfmu 0.7.0 releases one reference too many to this namespace at every
# fmi2Instantiate (see UniversalJoint.py); one reference per run keeps the count right.
ctypes.pythonapi.Py_IncRef(ctypes.py_object(globals()))


class CompliantJoint(CompliantJointSlave):
    start_overrides = {}
