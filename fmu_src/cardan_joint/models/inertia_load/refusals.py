"""The InertiaLoad's own reasons to refuse a step (registered with the shared ones)."""

from enum import Enum

from ...framework.refusal import register_reasons


class InertiaLoadReason(str, Enum):
    LOAD_SPEED = "load_speed"  # the inertia load's speed out of range at step end


register_reasons(
    InertiaLoadReason,
    {
        InertiaLoadReason.LOAD_SPEED: "input drive_torque = {drive_torque} N.m over a step of "
        "{step_size} s drives the load speed to {value} rad/s, beyond the limit {limit} rad/s"
    },
    {InertiaLoadReason.LOAD_SPEED: ("speed", "rad/s", "")},
)
