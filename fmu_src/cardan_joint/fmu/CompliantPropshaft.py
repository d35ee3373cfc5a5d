"""pythonfmu script of the CompliantPropshaft FMU (N joints; the build writes N
into `build_settings`; see `Propshaft.py`)."""

import ctypes

from cardan_joint.fmu.compliant_propshaft_slave import CompliantPropshaftSlave

# pythonfmu 0.7.0's loader re-runs this file at every fmi2Instantiate and then
# releases one reference too many to this module's namespace (see
# UniversalJoint.py): one reference per run keeps the count right.
ctypes.pythonapi.Py_IncRef(ctypes.py_object(globals()))


class CompliantPropshaft(CompliantPropshaftSlave):
    build_settings = {}
    start_overrides = {}
