"""Unit conversions, each named for its direction: `X_TO_Y` multiplies a value in X into Y.

The FMU works in SI (rad, rad/s, rad/s2); people read degrees and rpm. One
name per factor so that a factor means the same thing everywhere (a bare `RPM`
or `DEG` once meant opposite conversions in different files). The factors are
defined beside the unit table in `variables` (which the FMU ships, so its
display units use the same numbers); import them from here.
"""

from .variables import DEG_TO_RAD, RAD_PER_S_TO_RPM, RAD_TO_DEG, RPM_TO_RAD_PER_S

__all__ = ["DEG_TO_RAD", "RAD_PER_S_TO_RPM", "RAD_TO_DEG", "RPM_TO_RAD_PER_S"]
