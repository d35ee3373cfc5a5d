"""The Motor's own reasons to refuse a step (registered with the shared ones)."""

from enum import Enum

from ...framework.refusal import register_reasons


class MotorReason(str, Enum):
    ROTOR_SPEED = "rotor_speed"  # the motor's speed out of range at step end


register_reasons(
    MotorReason,
    {
        MotorReason.ROTOR_SPEED: "input load_torque = {load_torque} N.m over a step of "
        "{step_size} s drives the rotor speed to {value} rad/s, beyond the limit {limit} rad/s"
    },
    {MotorReason.ROTOR_SPEED: ("speed", "rad/s", "")},
)
