"""The Propshaft's step entry, one definition for any number of joints: the
runtime passes the step state (`step.state_names`) and the inputs flat, by
name (docs/codegen.md), and `PROPSHAFT_GROUPS` gathers them into
`step.propshaft_advanced`'s tuples."""

from ...framework.written_step import grouped_step
from .step import propshaft_advanced, state_names, takes_step
from .variables import JOINTS, propshaft_table

# The step state's names (`state_names`, for any number of joints) each tuple
# of `propshaft_step` takes.
PROPSHAFT_GROUPS = {
    "angle": ("turns", "fraction", "fraction_error"),
    "layout": (
        "joint_*_working_angle",
        "joint_*_pin_offset",
        "joint_*_twist",
        "joint_*_phase",
        "joint_*_inertia",
    ),
    "trig": (
        "joint_*_bend_sine",
        "joint_*_bend_cosine",
        "joint_*_turn_sine",
        "joint_*_turn_cosine",
    ),
    "shifts": ("shaft_*_shift",),
    "critical_speeds": ("shaft_*_critical_speed",),
    "fixed": ("speed_ratio_fluctuation", "equivalent_angle"),
    "crosspiece": ("crosspiece_inertia_*",),
    "life": (
        "bearing_radius",
        "rated_torque",
        "life_constant",
        "life_exponent",
        "life_min_angle",
        "life_rate_scale",
    ),
    "sums": ("joint_*_life_consumed", "joint_*_life_consumed_error"),
    "ahead": ("life_ahead_*", "joint_*_life_ahead_*"),
}


def propshaft_step(time, h, angle: tuple[int, float, float], parameters_valid: bool, layout, trig,
                   shifts, critical_speeds, fixed, crosspiece, life, singularity_reach, sums,
                   ahead, input_speed, input_acceleration,
                   load_torque) -> tuple | None:  # fmt: skip
    """The Propshaft's step (`state_names`, then the inputs, grouped):
    `propshaft_advanced`, or None when the step is not taken here (the model's
    checks then name the refusal)."""
    if not takes_step(h, parameters_valid, input_speed, input_acceleration, load_torque):
        return None
    return propshaft_advanced(h, angle, parameters_valid, layout, trig, shifts, critical_speeds,
                              fixed, crosspiece, life, singularity_reach, sums, ahead, input_speed,
                              input_acceleration, load_torque)  # fmt: skip


# The entry for each number of joints (the spec's `step`).
STEPS = {
    joints: grouped_step(
        f"propshaft_{joints}_step",
        propshaft_step,
        state_names(joints),
        propshaft_table(joints),
        PROPSHAFT_GROUPS,
    )
    for joints in JOINTS
}
