"""The compliant drive's own reason to refuse a step (registered with the shared
ones; the CompliantPropshaft's drive is this one too)."""

from enum import Enum

from ...framework.refusal import register_reasons


class CompliantReason(str, Enum):
    TWIST_OVERFLOW = "twist_overflow"  # a compliant drive's twist changing by > 1e15 rad


register_reasons(
    CompliantReason,
    {
        CompliantReason.TWIST_OVERFLOW: "the shaft speeds over a step of {step_size} s would "
        "change the twist_angle by {value} rad, beyond the limit {limit} rad per step"
    },
    {CompliantReason.TWIST_OVERFLOW: ("twist_angle", "rad", "")},
)
