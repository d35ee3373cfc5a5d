"""The compliant joint's step, written once: the definition `CompliantJoint.run`
runs and the build translates into the FMU's C runtime (docs/codegen.md), so
both give the same bits. The rigid joint's step (`universal_joint.step`) with
the spring-damper at its output.

The spring's functions take the rigid drive's kinematic values (its kinematic
offset, the kinematic output angle - input angle, and its kinematic output
speed), so every compliant drive shares them (the CompliantPropshaft too).
"""

import math

from ...framework.values import MAX_INCREMENT, bounds
from ...framework.written_step import grouped_step
from ...physics.life import LifeRule, step_damage_loaded
from ...physics.life_torque import turned
from ...physics.response import (
    cardan_error_at,
    crosspiece_motion,
    euler_moments,
    pose_of,
    yoke_reactions,
)
from ..universal_joint import variables as joint_table
from ..universal_joint.step import (
    LIFE_STATE,
    MOVED,
    joint_advanced,
    joint_outputs,
    life_added,
    life_of,
    takes_step,
)
from ..universal_joint.step import STATE as JOINT_STATE
from .variables import COMPLIANT_JOINT

# The step state: the rigid joint's with life, then the lag = input angle -
# output angle (the spring's own state, `CompliantDrive`).
STATE = (*LIFE_STATE, "lag")
# `joint_advanced`'s results: its state, its moved inputs, its outputs.
_JOINT = len(JOINT_STATE)
_END_SPEED, _END_BEND, _END_RATE = (
    _JOINT + joint_table.INPUTS.index(name)
    for name in ("input_speed", "bend_angle", "bend_angle_rate")
)
# The output shaft's inputs: symmetric ranges, so |x| <= max checks each (NaN fails).
OUTPUT_SPEED_LIMIT = bounds(COMPLIANT_JOINT.BY_NAME["output_speed"])[1]
OUTPUT_ACCELERATION_LIMIT = bounds(COMPLIANT_JOINT.BY_NAME["output_acceleration"])[1]
assert all(
    bounds(COMPLIANT_JOINT.BY_NAME[n])[0] == -bounds(COMPLIANT_JOINT.BY_NAME[n])[1]
    for n in ("output_speed", "output_acceleration")
), "the output shaft's ranges must be symmetric"
# The joint's outputs (`joint_outputs`, the table's order) the spring takes;
# from the cardan error on, they are the compliant joint's outputs too.
_INPUT_ANGLE, _KINEMATIC_SPEED, _OFFSET = (
    joint_table.OUTPUTS.index(name) for name in ("input_angle", "output_speed", "cardan_error")
)
_PASSED = _OFFSET
assert (
    COMPLIANT_JOINT.OUTPUTS[-len(joint_table.OUTPUTS[_PASSED:]) :] == joint_table.OUTPUTS[_PASSED:]
), "the compliant joint's outputs end with the joint's from cardan_error on"


# --- the spring-damper layer, from the rigid drive's kinematic values -------


def twist_change(
    h: float,
    input_speed: float,
    input_acceleration: float,
    output_speed: float,
    output_acceleration: float,
) -> float:
    """The lag's change over `h` s: the input angle's increment minus the output
    angle's, both exact polynomials, taken as one difference of the speeds."""
    return h * ((input_speed - output_speed) + 0.5 * (input_acceleration - output_acceleration) * h)


def spring_takes_step(output_speed: float, output_acceleration: float, change: float) -> bool:
    """Whether the spring lets the step be taken (with the rigid drive's
    `takes_step`): the output shaft's inputs in range, the twist's change at
    most MAX_INCREMENT. NaN fails every comparison."""
    return (
        abs(output_speed) <= OUTPUT_SPEED_LIMIT
        and abs(output_acceleration) <= OUTPUT_ACCELERATION_LIMIT
        and abs(change) <= MAX_INCREMENT
    )


def spring_torque(
    twist: float, kinematic_speed: float, output_speed: float, stiffness: float, damping: float
) -> float:
    """The torque on the output shaft: k twist + c (kinematic speed - output speed)."""
    return stiffness * twist + damping * (kinematic_speed - output_speed)


def spring_load(
    t: float,
    offset: float,
    kinematic_speed: float,
    lag: float,
    input_speed: float,
    input_acceleration: float,
    output_speed: float,
    output_acceleration: float,
    stiffness: float,
    damping: float,
) -> float:
    """The spring's torque `t` s into a step that starts at `lag` with these
    shaft motions, from the rigid drive's kinematic offset and speed then: the
    load its life integrates."""
    change = twist_change(t, input_speed, input_acceleration, output_speed, output_acceleration)
    twist = offset + (lag + change)
    speed = output_speed + output_acceleration * t
    return spring_torque(twist, kinematic_speed, speed, stiffness, damping)


def spring_outputs(
    input_angle: float,
    lag: float,
    offset: float,
    kinematic_speed: float,
    output_speed: float,
    stiffness: float,
    damping: float,
) -> tuple[float, float, float, float, float, float]:
    """(input_angle, output_angle, twist_angle, output_torque,
    kinematic_output_speed, spring_energy) now; output_torque is the rigid
    drive's load."""
    twist = offset + lag
    torque = spring_torque(twist, kinematic_speed, output_speed, stiffness, damping)
    energy = 0.5 * stiffness * twist * twist
    return (input_angle, input_angle - lag, twist, torque, kinematic_speed, energy)


# --- the joint under the spring ------------------------------------------------


def spring_loaded_torque(t: float, step) -> tuple[float, float]:
    """(T1, input speed) `t` s into a step of the joint under the spring:
    `step` = `life_torque.joint_torque`'s with the spring's start (lag, the
    output shaft's speed and acceleration, k, c) in place of the load, the
    bend's sine and cosine at the start last. The kernel's parts T1 and the
    spring need (`response`): T1 is affine in the load with slope cos b / D
    (the speed ratio), so the kinematics give the spring's torque and T1
    without load gives T1 under it."""
    psi, b, w1, a1, rb, ab, I1, I2, I3, lag, wo, ao, stiffness, damping, sb0, cb0 = step
    speed = w1 + a1 * t
    sb, cb = turned(b, sb0, cb0, t * (rb + 0.5 * ab * t))
    s, c, sb, cb, D, rD = pose_of(math, psi + t * (w1 + 0.5 * a1 * t), sb, cb)[2:]
    motion = crosspiece_motion(s, c, sb, cb, D, rD, speed, a1, rb + ab * t, ab)
    M1, M2, M3 = euler_moments(I1, I2, I3, *motion[2:])
    unloaded = yoke_reactions(M1, M2, M3, s, c, sb, cb, rD, 0.0)[2]
    load = spring_load(
        t, cardan_error_at(math, s, c, sb, cb), motion[0], lag, w1, a1, wo, ao, stiffness, damping
    )
    return unloaded + cb / D * load, speed


# The step state's and parameters' names each tuple of `compliant_joint_advanced`
# takes (`framework.grouped_entry.GroupedEntry`).
GROUPS = {
    "angle": ("turns", "fraction", "fraction_error"),
    "phase": ("phase_turns", "phase_fraction", "phase_error"),
    "miner": ("life_consumed", "life_consumed_error"),
    "starts": ("yoke_phase", "input_angle_start", "twist_angle_start"),
    "spring": ("torsional_stiffness", "torsional_damping"),
    "inertia": ("crosspiece_inertia_*",),
    "life": ("bearing_radius", "rated_torque", "life_constant", "life_exponent", "life_min_angle"),
}


def compliant_joint_advanced(
    time: float,
    h: float,
    angle: tuple[int, float, float],
    phase: tuple[int, float, float],
    parameters_valid: bool,
    miner,
    life_rate_scale: float,
    lag: float,
    input_speed: float,
    input_acceleration: float,
    output_speed: float,
    output_acceleration: float,
    bend_angle: float,
    bend_angle_rate: float,
    bend_angle_acceleration: float,
    starts,
    spring,
    inertia,
    max_bend_angle: float,
    life,
) -> tuple | None:
    """A step of `h` s from `time` (`STATE`, the inputs and the parameters,
    grouped as `GROUPS` says): the state, the inputs after the step and the
    outputs, or None when the step is not taken here (the model's checks then
    name the refusal). The rigid joint steps with no load (its kinematics do
    not depend on it); the spring's torque at the step's end is its load for
    the outputs, and the spring's torque over the step for the damage Miner's
    sum gains (from the values before the step). The start angles enter
    through the state (`start` reduces them)."""
    joint_inputs = (input_speed, input_acceleration, bend_angle, bend_angle_rate,
                    bend_angle_acceleration, 0.0)  # fmt: skip
    change = twist_change(h, input_speed, input_acceleration, output_speed, output_acceleration)
    if not (
        takes_step(h, parameters_valid, *joint_inputs, max_bend_angle)
        and spring_takes_step(output_speed, output_acceleration, change)
    ):
        return None
    stiffness, damping = spring
    free = joint_advanced(h, *angle, *phase, parameters_valid, *joint_inputs, *inertia)
    bearing_radius, rated_torque, life_constant, life_exponent, life_min_angle = life
    rule = LifeRule(rated_torque, life_constant, life_exponent, life_min_angle, life_rate_scale)
    psi = angle[1] + (phase[1] + (angle[2] + phase[2]))  # as `response`'s
    loading = (lag, output_speed, output_acceleration, stiffness, damping)
    damage = step_damage_loaded(
        rule, h, psi, bend_angle, input_speed, input_acceleration, bend_angle_rate,
        bend_angle_acceleration, inertia, spring_loaded_torque, loading,
    )  # fmt: skip
    consumed = life_added(miner[0], miner[1], damage)
    end_lag = lag + change
    end_output_speed = output_speed + output_acceleration * h
    end_speed, end_beta, end_rate = free[_END_SPEED], free[_END_BEND], free[_END_RATE]
    kinematic = free[MOVED:]  # the joint's outputs without load
    spring_values = spring_outputs(
        kinematic[_INPUT_ANGLE], end_lag, kinematic[_OFFSET], kinematic[_KINEMATIC_SPEED],
        end_output_speed, stiffness, damping,
    )  # fmt: skip
    load = spring_values[3]
    outputs = joint_outputs(
        free[:3], free[3:6], end_beta, end_speed, input_acceleration, end_rate,
        bend_angle_acceleration, load, *inertia,
    )  # fmt: skip
    life_values = life_of(rule, bearing_radius, consumed, outputs, load, end_speed, end_beta)
    moved = (end_speed, input_acceleration, end_output_speed, output_acceleration, end_beta,
             end_rate, bend_angle_acceleration)  # fmt: skip
    return (*free[:_JOINT], *consumed, life_rate_scale, end_lag, *moved, *spring_values,
            *outputs[_PASSED:], *life_values)  # fmt: skip


# The entry (the spec's `step`): the runtime's flat arguments, grouped.
compliant_joint_step = grouped_step(
    "compliant_joint_step", compliant_joint_advanced, STATE, COMPLIANT_JOINT, GROUPS
)
