"""The one table of the FMU's variables: names, causality, units, limits, starts.

Registration, the model description (units, display units, min/max,
variability, initial, ModelStructure dependencies), the physics model's default
values and the README's variable table are all generated from `VARIABLES`, for
FMI 2.0 and FMI 3.0 alike: `fmi3_variables()` groups the rows of a vector
(`<stem>_<i>`, named in `ARRAY_STEMS`) into one FMI 3 array.
Pure data: no FMI import, so the physics can read its defaults from here.
"""

import math

from ...units import DEG_TO_RAD
from ...units import JOINT_UNITS as UNITS
from ...variable_schema import _IN, _OUT, _PAR, Variable, VariableTable, fmi3_groups

# Inputs each output depends on directly (FMI ModelStructure "dependencies").
# Declaring them lets a master see that speed flows downstream without the load,
# so closing the torque loop through `load_torque` is no algebraic loop for speeds.
_POSE = ("bend_angle",)
_SPEED = ("input_speed", "bend_angle", "bend_angle_rate")
_ACCELERATION = (
    "input_speed",
    "input_acceleration",
    "bend_angle",
    "bend_angle_rate",
    "bend_angle_acceleration",
)
_TORQUE = _ACCELERATION + ("load_torque",)


HALF_PI = 0.5 * math.pi

# A table, one row per variable: kept as rows rather than one argument per line.
# fmt: off
VARIABLES = (
    # Inputs: polynomial in time over a step (speed with its acceleration, bend
    # angle with its rate and acceleration); the start values run a default demo.
    # Their ranges are physical bounds, generous for any driveline, that keep every
    # output finite; a step with an input outside them is refused.
    Variable("input_speed", _IN, "rad/s", "Input shaft speed omega1", 10.0, "rpm", -1e5, 1e5),
    Variable("input_acceleration", _IN, "rad/s2", "Input shaft acceleration a1 = d(omega1)/dt",
             0.0, "rpm/s", -1e8, 1e8),
    Variable("bend_angle", _IN, "rad", "Bend angle beta between the shafts (0 = straight)",
             math.pi / 6, "deg", -HALF_PI, HALF_PI),
    Variable("bend_angle_rate", _IN, "rad/s", "Bend angle rate d(beta)/dt", 0.0, "deg/s",
             -1e3, 1e3),
    Variable("bend_angle_acceleration", _IN, "rad/s2", "Bend angle acceleration d2(beta)/dt2",
             0.0, "deg/s2", -1e6, 1e6),
    Variable("load_torque", _IN, "N.m", "Load torque T_L the driven machine takes from the "
             "output shaft", 0.0, None, -1e9, 1e9),
    # Parameters.
    # Angles beyond 1e15 rad have no fractional digits left in a float.
    Variable("yoke_phase", _PAR, "rad", "Input-yoke pin angle from the bend plane at zero "
             "input angle (0: Wikipedia/maker/Tataru convention; 90 deg: Mityushov & Misyura)",
             0.0, "deg", -1e15, 1e15),
    Variable("input_angle_start", _PAR, "rad", "Input shaft angle gamma1 at the start time",
             0.0, "deg", -1e15, 1e15),
    Variable("crosspiece_inertia_1", _PAR, "kg.m2", "Crosspiece principal moment of inertia "
             "about the input-yoke pin", 0.026, None, 0.0, 1e6),
    Variable("crosspiece_inertia_2", _PAR, "kg.m2", "Crosspiece principal moment of inertia "
             "about the output-yoke pin", 0.026, None, 0.0, 1e6),
    Variable("crosspiece_inertia_3", _PAR, "kg.m2", "Crosspiece principal moment of inertia "
             "about the normal of the cross", 0.026, None, 0.0, 1e6),
    Variable("max_bend_angle", _PAR, "rad", "Largest |bend angle| accepted; a step reaching "
             "it is refused (the joint locks at 90 deg)", 80.0 * DEG_TO_RAD, "deg", 0.0, HALF_PI),
    # Outputs.
    Variable("input_angle", _OUT, "rad", "Input shaft angle gamma1", display_unit="deg"),
    Variable("output_angle", _OUT, "rad", "Output shaft angle gamma2 = gamma1 + cardan error "
             "(continuous)", display_unit="deg", depends_on=_POSE),
    Variable("output_speed", _OUT, "rad/s", "Output shaft speed omega2", display_unit="rpm",
             depends_on=_SPEED),
    Variable("output_acceleration", _OUT, "rad/s2", "Output shaft acceleration a2",
             display_unit="rpm/s", depends_on=_ACCELERATION),
    Variable("cardan_error", _OUT, "rad", "Cardan error gamma2 - gamma1", display_unit="deg",
             depends_on=_POSE),
    Variable("speed_ratio", _OUT, "1", "Speed ratio cos(beta)/D = omega2/omega1 at constant "
             "bend angle", min=0.0, depends_on=_POSE),
    Variable("crosspiece_angular_velocity_1", _OUT, "rad/s", "Crosspiece angular velocity "
             "about the input-yoke pin", display_unit="rpm", depends_on=_SPEED),
    Variable("crosspiece_angular_velocity_2", _OUT, "rad/s", "Crosspiece angular velocity "
             "about the output-yoke pin", display_unit="rpm", depends_on=_SPEED),
    Variable("crosspiece_angular_velocity_3", _OUT, "rad/s", "Crosspiece angular velocity "
             "about the cross normal", display_unit="rpm", depends_on=_SPEED),
    Variable("crosspiece_torque_1", _OUT, "N.m", "Resultant torque on the crosspiece (Euler), "
             "input-pin component", depends_on=_ACCELERATION),
    Variable("crosspiece_torque_2", _OUT, "N.m", "Resultant torque on the crosspiece (Euler), "
             "output-pin component", depends_on=_ACCELERATION),
    Variable("crosspiece_torque_3", _OUT, "N.m", "Resultant torque on the crosspiece (Euler), "
             "normal component", depends_on=_ACCELERATION),
    Variable("crosspiece_kinetic_energy", _OUT, "J", "Crosspiece kinetic energy", min=0.0,
             depends_on=_SPEED),
    Variable("crosspiece_quaternion_0", _OUT, "1", "Crosspiece orientation quaternion, scalar "
             "part", min=-1.0, max=1.0, depends_on=_POSE),
    Variable("crosspiece_quaternion_1", _OUT, "1", "Crosspiece orientation quaternion, x part",
             min=-1.0, max=1.0, depends_on=_POSE),
    Variable("crosspiece_quaternion_2", _OUT, "1", "Crosspiece orientation quaternion, y part",
             min=-1.0, max=1.0, depends_on=_POSE),
    Variable("crosspiece_quaternion_3", _OUT, "1", "Crosspiece orientation quaternion, z part",
             min=-1.0, max=1.0, depends_on=_POSE),
    Variable("input_torque", _OUT, "N.m", "Torque T1 the input shaft must supply",
             depends_on=_TORQUE),
    Variable("input_yoke_moment", _OUT, "N.m", "Secondary couple on the input yoke (bending "
             "moment normal to the input shaft)", min=0.0, depends_on=_TORQUE),
    Variable("output_yoke_moment", _OUT, "N.m", "Secondary couple on the output yoke (bending "
             "moment normal to the output shaft)", min=0.0, depends_on=_TORQUE),
)
# fmt: on


# This module is the UniversalJoint's table: the same lookups as every VariableTable.
_TABLE = VariableTable(VARIABLES, UNITS)
BY_NAME, INPUTS, PARAMETERS, OUTPUTS = (
    _TABLE.BY_NAME,
    _TABLE.INPUTS,
    _TABLE.PARAMETERS,
    _TABLE.OUTPUTS,
)
start_values = _TABLE.start_values

# Vector quantities: FMI 2 has one row per element (`<stem>_<i>`); FMI 3 declares
# each as one Float64 array named by the stem, elements in the rows' order.
ARRAY_STEMS = ("crosspiece_angular_velocity", "crosspiece_torque", "crosspiece_quaternion")


def fmi3_variables() -> tuple:
    """The FMI 3 variables in table order: arrays where ARRAY_STEMS says, else scalars."""
    return fmi3_groups(VARIABLES, ARRAY_STEMS)


def markdown_table() -> str:
    """The README's variable table (a test keeps the README in step)."""
    return _TABLE.markdown_table()
