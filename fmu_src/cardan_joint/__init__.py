"""Exact Cardan (Hooke) universal joint.

`cardan_joint.physics` holds every equation (pure Python + numpy, no FMI);
`cardan_joint.fmi` maps FMI variables onto it; `cardan_joint.build` and
`cardan_joint.host.simulate` wrap pythonfmu and FMPy. Nothing is imported eagerly so
that the physics stays importable without the FMI stack.
"""

__version__ = "1.1.0"
