"""Unit conversions, each named for its direction: `X_TO_Y` multiplies a value in X into Y.

The FMU works in SI (rad, rad/s, rad/s2); people read degrees and rpm. One
name per factor so that a factor means the same thing everywhere (a bare `RPM`
or `DEG` once meant opposite conversions in different files). The FMU ships
this module (build.RUNTIME): its display units use the same numbers.
"""

import math

RAD_TO_DEG = 180.0 / math.pi
DEG_TO_RAD = math.pi / 180.0
RAD_PER_S_TO_RPM = 30.0 / math.pi
RPM_TO_RAD_PER_S = math.pi / 30.0

__all__ = ["DEG_TO_RAD", "RAD_PER_S_TO_RPM", "RAD_TO_DEG", "RPM_TO_RAD_PER_S"]
