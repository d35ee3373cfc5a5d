"""Variable table of the InertiaLoad FMU: a driven machine with inertia (a state).

Same records and units as the Motor's and the Load's tables
(`units.table_of`). Pure data: the physics reads its defaults and ranges here.
"""

from ...units import table_of
from ...variable_schema import _IN, _OUT, _PAR, Variable

# A table, one row per variable: kept as rows rather than one argument per line.
# fmt: off
INERTIA_LOAD = table_of((
    Variable("drive_torque", _IN, "N.m", "Torque the drive applies to the load shaft (the "
             "compliant drive's output_torque), held over a step", 0.0, None, -1e9, 1e9),
    Variable("inertia", _PAR, "kg.m2", "Polar moment of inertia J of the driven machine",
             0.5, None, 1e-9, 1e6),
    Variable("drag", _PAR, "N.m.s/rad", "Viscous drag coefficient c of the driven machine",
             0.1, None, 0.0, 1e6),
    Variable("constant_torque", _PAR, "N.m", "Constant torque T0 the driven machine takes "
             "(also at standstill: it is not a friction)", 20.0, None, -1e9, 1e9),
    Variable("speed_start", _PAR, "rad/s", "Load speed at the start time", 0.0, "rpm",
             -1e5, 1e5),
    Variable("angle_start", _PAR, "rad", "Load angle at the start time", 0.0, "deg",
             -1e15, 1e15),
    Variable("speed", _OUT, "rad/s", "Load speed omega (the state)", display_unit="rpm"),
    Variable("acceleration", _OUT, "rad/s2", "Load acceleration (drive_torque - c omega - T0) "
             "/ J", display_unit="rpm/s", depends_on=("drive_torque",)),
    Variable("angle", _OUT, "rad", "Load angle", display_unit="deg"),
))
# fmt: on
