"""Unit conversions, each named for its direction: `X_TO_Y` multiplies a value in X into Y.

The FMU works in SI (rad, rad/s, rad/s2); people read degrees and rpm. One
name per factor so that a factor means the same thing everywhere (a bare `RPM`
or `DEG` once meant opposite conversions in different files). The FMU ships
this module (build.RUNTIME): its display units use the same numbers.
"""

import math

from .variable_schema import Unit, VariableTable

RAD_TO_DEG = 180.0 / math.pi
DEG_TO_RAD = math.pi / 180.0
RAD_PER_S_TO_RPM = 30.0 / math.pi
RPM_TO_RAD_PER_S = math.pi / 30.0

JOINT_UNITS = {
    u.name: u
    for u in (
        Unit("rad", (("rad", 1),), (("deg", RAD_TO_DEG),)),
        Unit("rad/s", (("rad", 1), ("s", -1)), (("rpm", RAD_PER_S_TO_RPM), ("deg/s", RAD_TO_DEG))),
        Unit(
            "rad/s2", (("rad", 1), ("s", -2)), (("rpm/s", RAD_PER_S_TO_RPM), ("deg/s2", RAD_TO_DEG))
        ),
        Unit("N.m", (("kg", 1), ("m", 2), ("s", -2))),
        Unit("kg.m2", (("kg", 1), ("m", 2))),
        Unit("J", (("kg", 1), ("m", 2), ("s", -2))),
        Unit("1", ()),
    )
}

# The bearing loads' and the catalogue life's units (docs/life.md).
LIFE_UNITS = {
    u.name: u
    for u in (
        Unit("m", (("m", 1),)),
        Unit("N", (("kg", 1), ("m", 1), ("s", -2))),
        Unit("1/h", (("s", -1),), factor=1.0 / 3600.0),
    )
}

# A propshaft tube's material (its critical speed).
TUBE_UNITS = {
    u.name: u
    for u in (
        Unit("m", (("m", 1),)),
        Unit("Pa", (("kg", 1), ("m", -1), ("s", -2))),
        Unit("kg/m3", (("kg", 1), ("m", -3))),
    )
}

# Every unit of the driveline's models (the joint's and the spring-damper's).
DRIVELINE_UNITS = {
    **JOINT_UNITS,
    **TUBE_UNITS,
    **LIFE_UNITS,
    "N.m.s/rad": Unit("N.m.s/rad", (("kg", 1), ("m", 2), ("s", -1), ("rad", -1))),
    "N.m/rad": Unit("N.m/rad", (("kg", 1), ("m", 2), ("s", -2), ("rad", -1))),
}


def table_of(variables) -> VariableTable:
    """A VariableTable declaring the units its variables use."""
    used = dict.fromkeys(v.unit for v in variables)
    return VariableTable(variables, {u: DRIVELINE_UNITS[u] for u in used})


__all__ = [
    "DRIVELINE_UNITS",
    "JOINT_UNITS",
    "LIFE_UNITS",
    "TUBE_UNITS",
    "table_of",
    "DEG_TO_RAD",
    "RAD_PER_S_TO_RPM",
    "RAD_TO_DEG",
    "RPM_TO_RAD_PER_S",
]
