"""pythonfmu3 script of the UniversalJoint FMU, FMI 3.0 co-simulation.

`build_fmu.py --fmi-version 3` copies this file into the FMU under a module
name unique to the build, and rewrites the import below to the copy of
`cardan_joint` it ships, so two FMUs of this project never share code in one
process.

pythonfmu3 0.3.4's loader imports this module once per process (an ordinary
import, new references released once) instead of re-running it at every
instantiation: it has no counterpart of pythonfmu 0.7.0's findClass reference
bug, so this script needs no compensating Py_IncRef (tests/test_fmi3.py
instantiates it many times in one process).
"""

from pythonfmu3 import Fmi3Slave

from cardan_joint.fmi.slave3 import CardanJointSlave3


# pythonfmu3's builder and C loader find the slave class by a regular expression
# that wants `Fmi3Slave` itself among the bases named on this line.
class UniversalJoint(CardanJointSlave3, Fmi3Slave):
    start_overrides = {}
