"""The Propshaft's own reasons to refuse its parameters (registered with the shared ones)."""

from enum import Enum

from ...framework.refusal import register_reasons


class PropshaftReason(str, Enum):
    SHAFT_ANGLE = "shaft_angle_invalid"  # a propshaft shaft angle not in (-pi/2, pi/2)
    WORKING_ANGLE_GUARD = "max_working_angle_invalid"  # max_working_angle not in (0, pi/2)
    WORKING_ANGLE = "working_angle"  # a joint's working angle >= the limit
    TUBE_BORE = "tube_bore"  # a tube's inner diameter >= its outer diameter


register_reasons(
    PropshaftReason,
    {
        PropshaftReason.SHAFT_ANGLE: "parameter {variable} = {value} rad ({value:deg} deg) must "
        "lie strictly between -pi/2 and pi/2 (a shaft cannot point across the driveline; "
        "limit {limit} rad)",
        PropshaftReason.WORKING_ANGLE_GUARD: "parameter max_working_angle = {value} rad "
        "({value:deg} deg) must lie strictly between 0 and pi/2 (90 deg, where a joint locks; "
        "limit {limit} rad)",
        PropshaftReason.WORKING_ANGLE: "{variable} = {value} rad ({value:deg} deg) is not below "
        "the limit max_working_angle = {limit} rad ({limit:deg} deg)",
        PropshaftReason.TUBE_BORE: "parameter {variable} = {value} m is not below the tube's "
        "outer diameter, limit {limit} m (a tube needs a wall)",
    },
    {
        PropshaftReason.SHAFT_ANGLE: (None, "rad", ""),
        PropshaftReason.WORKING_ANGLE_GUARD: ("max_working_angle", "rad", ""),
        PropshaftReason.WORKING_ANGLE: (None, "rad", ""),
        PropshaftReason.TUBE_BORE: (None, "m", ""),
    },
)
