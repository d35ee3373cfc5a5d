"""Exact Cardan (Hooke) universal joint.

`cardan_joint.physics` holds every equation (pure Python + numpy, no FMI);
`cardan_joint.fmi` maps FMI variables onto it; `cardan_joint.build` and
`cardan_joint.host.simulate` wrap pythonfmu and FMPy. Nothing is imported eagerly so
that the physics stays importable without the FMI stack.
"""

__version__ = "2.0.0"
# The model a command builds or runs when none is named: the project's own. The
# generic layers (build, host, fmi) take it from here and name no model.
DEFAULT_MODEL = "UniversalJoint"
