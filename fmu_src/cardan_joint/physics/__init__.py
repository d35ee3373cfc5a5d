"""The equations every model shares: pure Python, no FMI import, no framework
(the stepped-model runtime is `framework/`).

Angles in rad, speeds in rad/s, torques in N.m. `psi` is the input-pin angle
(input angle + yoke phase), `beta` the bend angle. `joint_response` holds every
closed form and works on Python scalars (through `math`, cheap enough for one
call per FMU step) and on numpy arrays (broadcast, no Python loops);
each model's own physics lives in its folder (`models/<name>/model.py`,
e.g. `CardanJoint` in `models/universal_joint/`).
"""

from .quantities import (
    cardan_error,
    degree_of_unevenness,
    max_cardan_error,
    output_angle,
    output_speed,
    roll_angle,
    speed_ratio,
)
from .response import JointResponse, joint_response
from .revolutions import RevolutionAngle, advance, split_angle
from .rotor import exact_rotor_step

__all__ = [
    "JointResponse",
    "RevolutionAngle",
    "advance",
    "cardan_error",
    "degree_of_unevenness",
    "exact_rotor_step",
    "joint_response",
    "max_cardan_error",
    "output_angle",
    "output_speed",
    "roll_angle",
    "speed_ratio",
    "split_angle",
]
