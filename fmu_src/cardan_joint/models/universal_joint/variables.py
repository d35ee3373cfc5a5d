"""The one table of the FMU's variables: names, causality, units, limits, starts.

Registration, the model description (units, display units, min/max,
variability, initial, ModelStructure dependencies), the physics model's default
values and the README's variable table are all generated from `VARIABLES`, for
FMI 2.0 and FMI 3.0 alike: `fmi3_variables()` groups the rows of a vector
(`<stem>_<i>`, named in `ARRAY_STEMS`) into one FMI 3 array.
Pure data: no FMI import, so the physics can read its defaults from here.
"""

import math

from ...units import DEG_TO_RAD, JOINT_UNITS, LIFE_UNITS
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
VARIABLES: tuple[Variable, ...] = (
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
# Bearing loads and catalogue life (docs/life.md): a build setting (`life`, on by
# default) leaves them out, so the joint's step can be measured without them.
LIFE_VARIABLES = (
    Variable("bearing_radius", _PAR, "m", "Trunnion bearing radius r: distance from the cross "
             "centre to the needle bearing's load line", 0.03, None, 1e-6, 10.0),
    Variable("rated_torque", _PAR, "N.m", "Rated torque T_r of the joint: the catalogue life "
             "is life_constant hours / (angle in deg x speed in rpm) at T1 = T_r",
             1000.0, None, 1e-6, 1e9),
    Variable("life_constant", _PAR, "1", "Catalogue life constant K (h x rpm x deg): "
             "L_h = K / (A n) (T_r/|T1|)^p", 1.5e6, None, 1e-9, 1e30),
    Variable("life_exponent", _PAR, "1", "Catalogue life exponent p (10/3: needle bearings)",
             10.0 / 3.0, None, 1.0, 10.0),
    Variable("life_min_angle", _PAR, "rad", "Smallest working angle A_min the life rule "
             "takes (the needles must roll)", 3.0 * DEG_TO_RAD, "deg", 0.0, HALF_PI),
    Variable("input_bearing_force", _OUT, "N", "Force on each input-yoke trunnion bearing, "
             "sqrt(T1^2 + C1^2) / (2 r)", min=0.0, depends_on=_TORQUE),
    Variable("output_bearing_force", _OUT, "N", "Force on each output-yoke trunnion bearing, "
             "sqrt(T_L^2 + C2^2) / (2 r)", min=0.0, depends_on=_TORQUE),
    Variable("life_rate", _OUT, "1/h", "Catalogue damage rate 1/L_h at this instant "
             "(0 at rest or without torque)", min=0.0, depends_on=_TORQUE),
    Variable("life_consumed", _OUT, "1", "Miner's sum of dt / (3600 L_h) since the start: "
             "1 = the B10 life used up", min=0.0),
)
# fmt: on


# Vector quantities: FMI 2 has one row per element (`<stem>_<i>`); FMI 3 declares
# each as one Float64 array named by the stem, elements in the rows' order.
ARRAY_STEMS = ("crosspiece_angular_velocity", "crosspiece_torque", "crosspiece_quaternion")
LIFE_NAMES = tuple(v.name for v in LIFE_VARIABLES)
WITHOUT_LIFE = VariableTable(VARIABLES, JOINT_UNITS, ARRAY_STEMS)
VARIABLES = (
    tuple(v for v in VARIABLES if v.causality != _OUT)
    + LIFE_VARIABLES[:5]
    + tuple(v for v in VARIABLES if v.causality == _OUT)
    + LIFE_VARIABLES[5:]
)

# This module is the UniversalJoint's table: the same lookups as every VariableTable.
_TABLE = VariableTable(VARIABLES, {**JOINT_UNITS, **LIFE_UNITS}, ARRAY_STEMS)
BY_NAME, INPUTS, PARAMETERS, OUTPUTS, UNITS = (
    _TABLE.BY_NAME,
    _TABLE.INPUTS,
    _TABLE.PARAMETERS,
    _TABLE.OUTPUTS,
    _TABLE.UNITS,
)
start_values = _TABLE.start_values


def table_for(life: bool = True):
    """The table of a build: this module, or with `life` off the one without the
    bearing and life rows (build setting `life`)."""
    import sys

    return sys.modules[__name__] if life else WITHOUT_LIFE


def fmi3_variables() -> tuple:
    """The FMI 3 variables in table order: arrays where ARRAY_STEMS says, else scalars."""
    return fmi3_groups(VARIABLES, ARRAY_STEMS)
