"""pythonfmu script of the Propshaft FMU (N joints; the build writes N into
`build_settings`).

`build_fmu.py --model Propshaft [--joints N]` copies this file into the FMU under
a module name unique to the build, and rewrites the import below to the copy of
`cardan_joint` it ships, so two FMUs of this project never share code in one
process.
"""

import ctypes

from cardan_joint.fmu.propshaft_slave import PropshaftSlave

# pythonfmu 0.7.0's loader re-runs this file at every fmi2Instantiate and then
# releases one reference too many to this module's namespace (see
# UniversalJoint.py): one reference per run keeps the count right.
ctypes.pythonapi.Py_IncRef(ctypes.py_object(globals()))


class Propshaft(PropshaftSlave):
    build_settings = {}
    start_overrides = {}
