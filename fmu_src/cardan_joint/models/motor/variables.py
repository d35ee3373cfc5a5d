"""Variable table of the Motor FMU: a rotor driven by a linear torque-speed
characteristic. Same `Variable` records and units as every model (`units.table_of`
declares only the units it uses). Pure data: the physics reads its defaults and
ranges here."""

from ...units import table_of
from ...variable_schema import _IN, _OUT, _PAR, Variable

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
