"""The Propshaft's step entries, one per number of joints: the step state
(`step.state_names`) and the inputs as the FMU's runtime passes them
(docs/codegen.md), grouped into `step.propshaft_advanced`'s tuples."""

from collections.abc import Callable

from .step import propshaft_advanced, takes_step


def propshaft_2_step(
    time, h, turns: int, fraction, fraction_error, parameters_valid: bool,
    joint_1_working_angle, joint_1_pin_offset, joint_1_twist, joint_1_phase, joint_1_inertia,
    joint_2_working_angle, joint_2_pin_offset, joint_2_twist, joint_2_phase, joint_2_inertia,
    shaft_1_shift, shaft_2_shift, shaft_1_critical_speed,
    speed_ratio_fluctuation, equivalent_angle, crosspiece_inertia_1, crosspiece_inertia_2,
    crosspiece_inertia_3,
    bearing_radius, rated_torque, life_constant, life_exponent, life_min_angle,
    joint_1_life_consumed, joint_1_life_consumed_error,
    joint_2_life_consumed, joint_2_life_consumed_error,
    input_speed, input_acceleration, load_torque,
) -> tuple | None:  # fmt: skip
    """The 2-joint Propshaft's step (`state_names(2)`, then the inputs):
    `propshaft_advanced`, or None when the step is not taken here (the
    model's checks then name the refusal)."""
    if not takes_step(h, parameters_valid, input_speed, input_acceleration, load_torque):
        return None
    layout = (
        joint_1_working_angle, joint_1_pin_offset, joint_1_twist, joint_1_phase, joint_1_inertia,
        joint_2_working_angle, joint_2_pin_offset, joint_2_twist, joint_2_phase, joint_2_inertia,
    )  # fmt: skip
    sums = (
        joint_1_life_consumed,
        joint_1_life_consumed_error,
        joint_2_life_consumed,
        joint_2_life_consumed_error,
    )
    return propshaft_advanced(
        h, (turns, fraction, fraction_error), parameters_valid, layout,
        (shaft_1_shift, shaft_2_shift),
        (shaft_1_critical_speed,),
        (speed_ratio_fluctuation, equivalent_angle),
        (crosspiece_inertia_1, crosspiece_inertia_2, crosspiece_inertia_3),
        (bearing_radius, rated_torque, life_constant, life_exponent, life_min_angle),
        sums, input_speed, input_acceleration, load_torque,
    )  # fmt: skip


def propshaft_3_step(
    time, h, turns: int, fraction, fraction_error, parameters_valid: bool,
    joint_1_working_angle, joint_1_pin_offset, joint_1_twist, joint_1_phase, joint_1_inertia,
    joint_2_working_angle, joint_2_pin_offset, joint_2_twist, joint_2_phase, joint_2_inertia,
    joint_3_working_angle, joint_3_pin_offset, joint_3_twist, joint_3_phase, joint_3_inertia,
    shaft_1_shift, shaft_2_shift, shaft_3_shift, shaft_1_critical_speed, shaft_2_critical_speed,
    speed_ratio_fluctuation, equivalent_angle, crosspiece_inertia_1, crosspiece_inertia_2,
    crosspiece_inertia_3,
    bearing_radius, rated_torque, life_constant, life_exponent, life_min_angle,
    joint_1_life_consumed, joint_1_life_consumed_error,
    joint_2_life_consumed, joint_2_life_consumed_error,
    joint_3_life_consumed, joint_3_life_consumed_error,
    input_speed, input_acceleration, load_torque,
) -> tuple | None:  # fmt: skip
    """`propshaft_2_step` for 3 joints."""
    if not takes_step(h, parameters_valid, input_speed, input_acceleration, load_torque):
        return None
    layout = (
        joint_1_working_angle, joint_1_pin_offset, joint_1_twist, joint_1_phase, joint_1_inertia,
        joint_2_working_angle, joint_2_pin_offset, joint_2_twist, joint_2_phase, joint_2_inertia,
        joint_3_working_angle, joint_3_pin_offset, joint_3_twist, joint_3_phase, joint_3_inertia,
    )  # fmt: skip
    sums = (
        joint_1_life_consumed,
        joint_1_life_consumed_error,
        joint_2_life_consumed,
        joint_2_life_consumed_error,
        joint_3_life_consumed,
        joint_3_life_consumed_error,
    )
    return propshaft_advanced(
        h, (turns, fraction, fraction_error), parameters_valid, layout,
        (shaft_1_shift, shaft_2_shift, shaft_3_shift),
        (shaft_1_critical_speed, shaft_2_critical_speed),
        (speed_ratio_fluctuation, equivalent_angle),
        (crosspiece_inertia_1, crosspiece_inertia_2, crosspiece_inertia_3),
        (bearing_radius, rated_torque, life_constant, life_exponent, life_min_angle),
        sums, input_speed, input_acceleration, load_torque,
    )  # fmt: skip


def propshaft_4_step(
    time, h, turns: int, fraction, fraction_error, parameters_valid: bool,
    joint_1_working_angle, joint_1_pin_offset, joint_1_twist, joint_1_phase, joint_1_inertia,
    joint_2_working_angle, joint_2_pin_offset, joint_2_twist, joint_2_phase, joint_2_inertia,
    joint_3_working_angle, joint_3_pin_offset, joint_3_twist, joint_3_phase, joint_3_inertia,
    joint_4_working_angle, joint_4_pin_offset, joint_4_twist, joint_4_phase, joint_4_inertia,
    shaft_1_shift, shaft_2_shift, shaft_3_shift, shaft_4_shift, shaft_1_critical_speed,
    shaft_2_critical_speed, shaft_3_critical_speed,
    speed_ratio_fluctuation, equivalent_angle, crosspiece_inertia_1, crosspiece_inertia_2,
    crosspiece_inertia_3,
    bearing_radius, rated_torque, life_constant, life_exponent, life_min_angle,
    joint_1_life_consumed, joint_1_life_consumed_error,
    joint_2_life_consumed, joint_2_life_consumed_error,
    joint_3_life_consumed, joint_3_life_consumed_error,
    joint_4_life_consumed, joint_4_life_consumed_error,
    input_speed, input_acceleration, load_torque,
) -> tuple | None:  # fmt: skip
    """`propshaft_2_step` for 4 joints."""
    if not takes_step(h, parameters_valid, input_speed, input_acceleration, load_torque):
        return None
    layout = (
        joint_1_working_angle, joint_1_pin_offset, joint_1_twist, joint_1_phase, joint_1_inertia,
        joint_2_working_angle, joint_2_pin_offset, joint_2_twist, joint_2_phase, joint_2_inertia,
        joint_3_working_angle, joint_3_pin_offset, joint_3_twist, joint_3_phase, joint_3_inertia,
        joint_4_working_angle, joint_4_pin_offset, joint_4_twist, joint_4_phase, joint_4_inertia,
    )  # fmt: skip
    sums = (
        joint_1_life_consumed,
        joint_1_life_consumed_error,
        joint_2_life_consumed,
        joint_2_life_consumed_error,
        joint_3_life_consumed,
        joint_3_life_consumed_error,
        joint_4_life_consumed,
        joint_4_life_consumed_error,
    )
    return propshaft_advanced(
        h, (turns, fraction, fraction_error), parameters_valid, layout,
        (shaft_1_shift, shaft_2_shift, shaft_3_shift, shaft_4_shift),
        (shaft_1_critical_speed, shaft_2_critical_speed, shaft_3_critical_speed),
        (speed_ratio_fluctuation, equivalent_angle),
        (crosspiece_inertia_1, crosspiece_inertia_2, crosspiece_inertia_3),
        (bearing_radius, rated_torque, life_constant, life_exponent, life_min_angle),
        sums, input_speed, input_acceleration, load_torque,
    )  # fmt: skip


# The entry for each number of joints (the spec's `step`).
STEPS: dict[int, Callable[..., tuple | None]] = {
    2: propshaft_2_step,
    3: propshaft_3_step,
    4: propshaft_4_step,
}
