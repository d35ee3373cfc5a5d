"""pythonfmu script of the InertiaLoad FMU (see `UniversalJoint.py` for how the build ships it)."""

import ctypes

from cardan_joint.fmu.inertia_load_slave import InertiaLoadSlave

# pythonfmu 0.7.0 releases one reference too many to this namespace at every
# fmi2Instantiate (see UniversalJoint.py); one reference per run keeps the count right.
ctypes.pythonapi.Py_IncRef(ctypes.py_object(globals()))


class InertiaLoad(InertiaLoadSlave):
    start_overrides = {}
