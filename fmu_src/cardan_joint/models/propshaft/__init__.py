"""Several Cardan joints in 3-D: a vehicle propshaft (models/propshaft/README.md).

`geometry` turns measured side-view and top-view shaft angles into each joint's
working angle and frame; `chain` evaluates the single joint's closed forms joint
after joint (speeds, accelerations, input torque, energy); `fluctuation` finds
the exact speed-ratio fluctuation and the best yoke phasing; `checks` applies
the joint makers' published angle rules; `model.Propshaft` steps it as the FMU
does. Pure Python; numpy only for arrays.
"""

from .chain import ChainState, chain
from .checks import AngleReport, angle_report, max_operating_angle
from .fluctuation import (
    best_phasing,
    equivalent_angle,
    speed_ratio_extrema,
    speed_ratio_fluctuation,
)
from .geometry import Layout, layout, plane_angle
from .model import Propshaft

__all__ = [
    "AngleReport",
    "ChainState",
    "Layout",
    "Propshaft",
    "angle_report",
    "best_phasing",
    "chain",
    "equivalent_angle",
    "layout",
    "max_operating_angle",
    "plane_angle",
    "speed_ratio_extrema",
    "speed_ratio_fluctuation",
]
