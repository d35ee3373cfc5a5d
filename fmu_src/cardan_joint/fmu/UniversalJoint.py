"""pythonfmu script of the UniversalJoint FMU.

`build_fmu.py` copies this file into the FMU under a module name unique to the
build, and rewrites the import below to the copy of `cardan_joint` it ships, so
two FMUs of this project never share code in one process.
"""

import ctypes

from cardan_joint.fmu.slave import CardanJointSlave

# pythonfmu 0.7.0's loader re-runs this file at every fmi2Instantiate and then
# releases one reference too many to this module's namespace (it Py_DECREFs the
# borrowed result of PyModule_GetDict). Taking one reference per run keeps the
# count right; without it the namespace is freed after a few instantiations and
# the host process crashes. An extra reference (when imported otherwise) only
# keeps the namespace alive.
ctypes.pythonapi.Py_IncRef(ctypes.py_object(globals()))


class UniversalJoint(CardanJointSlave):
    start_overrides = {}
