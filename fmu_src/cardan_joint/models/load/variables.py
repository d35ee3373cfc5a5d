"""Variable table of the Load FMU: a driven machine with inertia, viscous drag and
a constant torque. Pure data: the physics reads its defaults and ranges here."""

from ...units import table_of
from ...variable_schema import _IN, _OUT, _PAR, Variable

LOAD = table_of(
    (
        Variable(
            "speed",
            _IN,
            "rad/s",
            "Load shaft speed (the drive element's output_speed)",
            0.0,
            "rpm",
            -1e5,
            1e5,
        ),
        Variable(
            "acceleration",
            _IN,
            "rad/s2",
            "Load shaft acceleration (the drive element's output_acceleration)",
            0.0,
            "rpm/s",
            -1e8,
            1e8,
        ),
        Variable(
            "inertia",
            _PAR,
            "kg.m2",
            "Polar moment of inertia of the driven machine",
            0.5,
            None,
            0.0,
            1e6,
        ),
        Variable(
            "drag",
            _PAR,
            "N.m.s/rad",
            "Viscous drag coefficient c of the driven machine",
            0.1,
            None,
            0.0,
            1e6,
        ),
        Variable(
            "constant_torque",
            _PAR,
            "N.m",
            "Constant torque T0 the driven machine takes",
            20.0,
            None,
            -1e9,
            1e9,
        ),
        Variable(
            "torque",
            _OUT,
            "N.m",
            "Torque the load takes from its shaft, J a + c omega + T0 "
            "(the drive element's load_torque)",
            depends_on=("speed", "acceleration"),
        ),
    )
)
