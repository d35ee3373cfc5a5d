"""The joint's step, written once: the definition `CardanJoint.run` runs and the
build translates into the FMU's C runtime (docs/codegen.md), so both give the
same bits. Pure functions of floats: the inputs held over the step, the
parameters, the input angle and yoke phase as exact revolutions
(`physics.revolutions`) and, with life on, Miner's sum (`joint_life_step`).
"""

import math

from ...framework.values import shaft_moves
from ...framework.written_step import grouped_step, sound_step
from ...physics.life import LifeRule, compensated_add, life_outputs, step_damage
from ...physics.response import JointResponse, kernel
from ...physics.revolutions import Turns, advanced, angle_value
from . import variables as table
from .limits import SPEED_LIMIT, fits

# After the two angles, the outputs are the kernel's leading fields, in order
# (then, with life on, the bearing loads and life: `JointLife._with_life`).
KINEMATIC_OUTPUTS = len(table.WITHOUT_LIFE.OUTPUTS) - 2
assert JointResponse._fields[:KINEMATIC_OUTPUTS] == table.WITHOUT_LIFE.OUTPUTS[2:], (
    "kernel's field order"
)
_CARDAN_ERROR = JointResponse._fields.index("cardan_error")
# The state the step advances beside the inputs: the input angle and the yoke
# phase as exact revolutions, and whether the parameters let it run (both fixed
# at `start`). A generated step takes (time, h, state, inputs, parameters) and
# gives (state, the inputs after the step, outputs): the FMU's runtime keeps
# these values in C (docs/codegen.md).
STATE = (
    "turns", "fraction", "fraction_error", "phase_turns", "phase_fraction", "phase_error",
    "parameters_valid",
)  # fmt: skip
ANGLE = STATE.index("phase_turns")  # the input angle's values lead the state
MOVED = len(STATE) + len(table.INPUTS)
# With life on, Miner's sum and its compensation follow (`JointLife`), then
# the life rule's scale (`life_rule`), fixed at `start` as the rule is.
LIFE_STATE = (*STATE, "life_consumed", "life_consumed_error", "life_rate_scale")
_KINEMATIC_STATE = len(STATE)
# The kernel's fields the bearing loads take, among the outputs after the angles.
_TORQUE, _INPUT_MOMENT, _OUTPUT_MOMENT = (
    JointResponse._fields.index(name)
    for name in ("input_torque", "input_yoke_moment", "output_yoke_moment")
)
_SPEED, _BEND, _LOAD = (table.INPUTS.index(name) for name in ("input_speed", "bend_angle",
                                                              "load_torque"))  # fmt: skip


def joint_outputs(
    angle: Turns,
    phase: Turns,
    beta: float,
    speed: float,
    acceleration: float,
    rate: float,
    bend_acceleration: float,
    load: float,
    I1: float,
    I2: float,
    I3: float,
) -> tuple:
    """The outputs without life, in the table's order, at input angle `angle`."""
    turns, fraction, error = angle
    phase_turns, phase_fraction, phase_error = phase
    # The quaternion has period 4 pi: its sign is (-1)^(whole turns of psi).
    sign = -1.0 if (turns + phase_turns) & 1 == 1 else 1.0
    psi = fraction + (phase_fraction + (error + phase_error))
    r = kernel(
        math, psi, beta, speed, acceleration, rate, bend_acceleration, I1, I2, I3, load, sign
    )
    input_angle = angle_value(angle)
    # Two roundings at most: within one ulp of gamma2 however many turns.
    return (input_angle, input_angle + r[_CARDAN_ERROR]) + r[:KINEMATIC_OUTPUTS]


def takes_step(
    h: float,
    parameters_valid: bool,
    speed: float,
    acceleration: float,
    beta: float,
    rate: float,
    bend_acceleration: float,
    load: float,
    max_bend_angle: float,
) -> bool:
    """Whether the step is taken here; otherwise the model's checks name the
    refusal. NaN fails every comparison, so a NaN anywhere is never taken here."""
    return (
        sound_step(h, parameters_valid)
        and fits(speed, acceleration, beta, rate, bend_acceleration, load, max_bend_angle, h)
        and shaft_moves(h, speed, acceleration, SPEED_LIMIT)
    )


def joint_advanced(
    h: float,
    turns: int,
    fraction: float,
    fraction_error: float,
    phase_turns: int,
    phase_fraction: float,
    phase_error: float,
    parameters_valid: bool,
    speed: float,
    acceleration: float,
    beta: float,
    rate: float,
    bend_acceleration: float,
    load: float,
    I1: float,
    I2: float,
    I3: float,
) -> tuple:
    """A step `takes_step` takes, of `h` s with the inputs held (speed and bend
    angle at constant acceleration): the state, the inputs after the step and
    the outputs without life."""
    increment = h * (speed + 0.5 * acceleration * h)
    end_speed = speed + acceleration * h
    angle = advanced((turns, fraction, fraction_error), increment)
    end_beta = beta + h * (rate + 0.5 * bend_acceleration * h)
    end_rate = rate + bend_acceleration * h
    moved = (end_speed, acceleration, end_beta, end_rate, bend_acceleration, load)
    phase = (phase_turns, phase_fraction, phase_error)
    outputs = joint_outputs(
        angle, phase, end_beta, end_speed, acceleration, end_rate, bend_acceleration, load,
        I1, I2, I3,
    )  # fmt: skip
    return angle + phase + (parameters_valid,) + moved + outputs


# The inputs held over a step, as the entries' functions take them (the
# table's `INPUTS`, in order).
Inputs = tuple[float, float, float, float, float, float]
# The step state's and parameters' names each tuple of the two entries'
# functions takes (`framework.grouped_entry.GroupedEntry`); the inputs travel
# as one tuple, in the table's order.
GROUPS = {
    "angle": ("turns", "fraction", "fraction_error"),
    "phase": ("phase_turns", "phase_fraction", "phase_error"),
    "inputs": table.INPUTS,
    "starts": ("yoke_phase", "input_angle_start"),
    "inertia": ("crosspiece_inertia_*",),
}
LIFE_GROUPS = {
    **GROUPS,
    "miner": ("life_consumed", "life_consumed_error"),
    "life": ("bearing_radius", "rated_torque", "life_constant", "life_exponent", "life_min_angle"),
}


def joint_without_life(time, h, angle: Turns, phase: Turns, parameters_valid: bool,
                       inputs: Inputs, starts, inertia,
                       max_bend_angle) -> tuple | None:  # fmt: skip
    """A step of `h` s from `time` without life (`STATE`, the inputs and the
    parameters, grouped as `GROUPS` says): the state, the inputs after the step
    and the outputs, or None when the step is not taken here. The yoke phase
    and start angle (`starts`) enter through the state (`start` reduces them),
    not as parameters."""
    if not takes_step(h, parameters_valid, *inputs, max_bend_angle):
        return None
    return joint_advanced(h, *angle, *phase, parameters_valid, *inputs, *inertia)


def joint_with_life(time, h, angle: Turns, phase: Turns, parameters_valid: bool, miner,
                    life_rate_scale, inputs: Inputs, starts, inertia, max_bend_angle,
                    life) -> tuple | None:  # fmt: skip
    """`joint_without_life` with life on (`LIFE_STATE`, grouped as
    `LIFE_GROUPS` says): the state, the inputs after the step, the outputs and
    the four life outputs; Miner's sum gains the step's damage
    (`life.step_damage`, from the values before the step)."""
    if not takes_step(h, parameters_valid, *inputs, max_bend_angle):
        return None
    taken = joint_advanced(h, *angle, *phase, parameters_valid, *inputs, *inertia)
    speed, acceleration, beta, rate, bend_acceleration, load = inputs
    bearing_radius, rated_torque, life_constant, life_exponent, life_min_angle = life
    rule = LifeRule(rated_torque, life_constant, life_exponent, life_min_angle, life_rate_scale)
    psi = angle[1] + (phase[1] + (angle[2] + phase[2]))  # as `response`'s
    damage = step_damage(
        rule, h, psi, beta, speed, acceleration, rate, bend_acceleration, inertia, load
    )
    consumed = life_added(miner[0], miner[1], damage)
    moved = taken[_KINEMATIC_STATE:MOVED]
    outputs = taken[MOVED:]
    life_values = life_of(rule, bearing_radius, consumed, outputs, moved[_LOAD], moved[_SPEED],
                          moved[_BEND])  # fmt: skip
    return taken[:_KINEMATIC_STATE] + consumed + (life_rate_scale,) + moved + outputs + life_values


# The entries (the spec's `step`): the runtime's flat arguments, grouped.
joint_step = grouped_step("joint_step", joint_without_life, STATE, table.WITHOUT_LIFE, GROUPS)
joint_life_step = grouped_step("joint_life_step", joint_with_life, LIFE_STATE, table, LIFE_GROUPS)


def life_added(consumed: float, consumed_error: float, damage: float) -> tuple[float, float]:
    """Miner's sum and its compensation with a step's damage added."""
    if damage != 0.0:
        return compensated_add(consumed, consumed_error, damage)
    return consumed, consumed_error


def life_of(
    rule: LifeRule,
    bearing_radius: float,
    consumed: tuple[float, float],
    outputs,
    load: float,
    speed: float,
    bend: float,
) -> tuple[float, float, float, float]:
    """The four life outputs after a step, from the joint's outputs
    (`joint_outputs`) and Miner's sum with its compensation."""
    kernel_fields = outputs[2:]  # after the two angles
    return life_outputs(
        rule, bearing_radius, consumed[0] + consumed[1], kernel_fields[_TORQUE],
        kernel_fields[_INPUT_MOMENT], kernel_fields[_OUTPUT_MOMENT], load, speed, bend,
    )  # fmt: skip
