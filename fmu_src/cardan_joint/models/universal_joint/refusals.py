"""The joint's own reasons to refuse a step or its parameters: the bend angle and
its guard (registered with the shared ones). Every jointed model refuses with them."""

from enum import Enum

from ...framework.refusal import register_reasons


class JointReason(str, Enum):
    BEND_ANGLE = "bend_angle"  # |bend angle| >= max_bend_angle now
    BEND_AT_STEP_END = "bend_angle_at_step_end"  # ... at the end of the step
    BEND_PEAK_IN_STEP = "bend_angle_peak_in_step"  # ... at the parabola's vertex inside it
    BEND_GUARD = "max_bend_angle_invalid"  # max_bend_angle not in (0, pi/2)


_LIMIT = "max_bend_angle = {limit} rad ({limit:deg} deg)"
_IN_STEP = (
    " with bend_angle_rate = {bend_angle_rate} rad/s and bend_angle_acceleration = "
    "{bend_angle_acceleration} rad/s2: not below the limit " + _LIMIT
)

register_reasons(
    JointReason,
    {
        JointReason.BEND_ANGLE: "input bend_angle = {value} rad ({value:deg} deg) is not below "
        "the limit " + _LIMIT,
        JointReason.BEND_AT_STEP_END: "input bend_angle reaches {value} rad ({value:deg} deg) at "
        "the end of the step, {after} s on," + _IN_STEP,
        JointReason.BEND_PEAK_IN_STEP: "input bend_angle peaks at {value} rad ({value:deg} deg) "
        "{after} s into the step," + _IN_STEP,
        JointReason.BEND_GUARD: "parameter max_bend_angle = {value} rad ({value:deg} deg) must "
        "lie strictly between 0 and pi/2 (90 deg, where the joint locks; limit {limit} rad)",
    },
    {
        JointReason.BEND_ANGLE: ("bend_angle", "rad", "input"),
        JointReason.BEND_AT_STEP_END: ("bend_angle", "rad", "input"),
        JointReason.BEND_PEAK_IN_STEP: ("bend_angle", "rad", "input"),
        JointReason.BEND_GUARD: ("max_bend_angle", "rad", "parameter"),
    },
)
