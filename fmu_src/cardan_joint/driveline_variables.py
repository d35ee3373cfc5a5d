"""Variable tables of the driveline's end pieces: the `Motor` and the `Load` FMU.

Same `Variable` records and units as the joint's table (`variables.py`); each
table is a `variables.VariableTable`, as the Propshaft's, declaring only the
units it uses. Pure data: the physics reads its defaults and ranges here.
"""

from .variable_schema import _IN, _OUT, _PAR, Unit, Variable, VariableTable
from .variables import UNITS as _JOINT_UNITS

# Every unit of the driveline's models (the joint's and the spring-damper's).
DRIVELINE_UNITS = {
    **_JOINT_UNITS,
    "N.m.s/rad": Unit("N.m.s/rad", (("kg", 1), ("m", 2), ("s", -1), ("rad", -1))),
    "N.m/rad": Unit("N.m/rad", (("kg", 1), ("m", 2), ("s", -2), ("rad", -1))),
}


def table_of(variables) -> VariableTable:
    """A VariableTable declaring the units its variables use."""
    used = dict.fromkeys(v.unit for v in variables)
    return VariableTable(variables, {u: DRIVELINE_UNITS[u] for u in used})


MOTOR = table_of(
    (
        Variable(
            "load_torque",
            _IN,
            "N.m",
            "Torque the driven shaft takes from the rotor "
            "(the drive element's input_torque), held over a step",
            0.0,
            None,
            -1e9,
            1e9,
        ),
        Variable(
            "stall_torque",
            _PAR,
            "N.m",
            "Motor torque at standstill; the characteristic "
            "falls linearly to zero at the no-load speed",
            60.0,
            None,
            1e-9,
            1e9,
        ),
        Variable(
            "no_load_speed",
            _PAR,
            "rad/s",
            "Speed at which the motor torque reaches zero",
            157.07963267948966,
            "rpm",
            1e-9,
            1e5,
        ),
        Variable(
            "rotor_inertia",
            _PAR,
            "kg.m2",
            "Polar moment of inertia of the rotor",
            0.05,
            None,
            1e-9,
            1e6,
        ),
        Variable(
            "speed_start", _PAR, "rad/s", "Rotor speed at the start time", 0.0, "rpm", -1e5, 1e5
        ),
        Variable(
            "angle_start", _PAR, "rad", "Rotor angle at the start time", 0.0, "deg", -1e15, 1e15
        ),
        Variable("speed", _OUT, "rad/s", "Rotor speed omega (the state)", display_unit="rpm"),
        Variable(
            "acceleration",
            _OUT,
            "rad/s2",
            "Rotor acceleration (T(omega) - load_torque) / J",
            display_unit="rpm/s",
            depends_on=("load_torque",),
        ),
        Variable("angle", _OUT, "rad", "Rotor angle", display_unit="deg"),
        Variable(
            "motor_torque",
            _OUT,
            "N.m",
            "Motor torque T(omega) = stall_torque (1 - omega / no_load_speed)",
        ),
    )
)

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
