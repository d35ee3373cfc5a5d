"""The propshaft's step, written once: the definition `Propshaft.run` runs and
the build translates into the FMU's C runtime (docs/codegen.md), so both give
the same bits. Pure functions of floats and fixed-size tuples: the input angle
as exact revolutions, the layout `start` fixes (`chain.layout_values`, the
branch shifts, the tubes' critical speeds, the fluctuation) and each joint's
Miner's sum travel in the state (`state_names`); a loop over the joints is a
loop over a tuple's positions, which the generator unrolls.

What follows from the parameters alone is computed once, when the model
starts, and travels in the state too (`fixed_by_layout`: the bends' and the
pins' turns' sines and cosines, the singularities' reach; the life rule's
scale, `physics.life.life_rule`), so no step computes it again.

The life of a step: each joint's damage is the integral of its rate, from
its torque T_k and its input shaft's speed, both the chain at that instant
(`chain_torque`); `step_integrals` takes every joint's on the same nodes, so
each node costs one chain for all the joints.
"""

import math

from ...framework.values import bounds, shaft_moves
from ...framework.written_step import sound_step
from ...physics.life import LifeRule, compensated_add, life_outputs, singularity_reach
from ...physics.life_integral import step_integrals
from ...physics.response import JointResponse, kernel_at
from ...physics.revolutions import advanced, angle_value
from .chain import (
    ACCELERATION,
    CHAIN_FIELDS,
    LAYOUT_FIELDS,
    LOAD,
    PIN,
    SPEED,
    TORQUE,
    WORKING_ANGLE,
    chain_backward,
    chain_values,
    node_forward,
    node_trig,
)
from .variables import propshaft_table

_BY_NAME = propshaft_table().BY_NAME  # every layout's inputs have the same ranges
SPEED_LIMIT, _ACCELERATION_LIMIT, _LOAD_LIMIT = (
    bounds(_BY_NAME[name])[1] for name in ("input_speed", "input_acceleration", "load_torque")
)
_INPUT_MOMENT, _OUTPUT_MOMENT = (
    JointResponse._fields.index(name) for name in ("input_yoke_moment", "output_yoke_moment")
)
# `chain_torque`'s step: (the input angle's fraction and error, the input
# speed and acceleration at the step's start, the cross's inertias, the load),
# then the layout and `node_trig`'s sines and cosines (`chain_damages`): nine
# numbers a joint.
_STEP_HEAD = 8
# `node_trig`'s values of a joint, as the step state names them: its bend's,
# then (after every joint's bend) its turn's to the next joint's pin.
_TRIG = (("bend_sine", "bend_cosine"), ("turn_sine", "turn_cosine"))
_JOINT_FIELDS = LAYOUT_FIELDS + 4


def state_names(joints: int) -> tuple[str, ...]:
    """The step state's names for `joints` joints: what the entries take after
    (time, h) and before the inputs, and `Propshaft.step_state()` gives."""
    layout = ("working_angle", "pin_offset", "twist", "phase", "inertia")
    return (
        "turns", "fraction", "fraction_error", "parameters_valid",
        *(f"joint_{k}_{name}" for k in range(1, joints + 1) for name in layout),
        *(f"joint_{k}_{name}" for part in _TRIG for k in range(1, joints + 1) for name in part),
        *(f"shaft_{k}_shift" for k in range(1, joints + 1)),
        *(f"shaft_{k}_critical_speed" for k in range(1, joints)),
        "speed_ratio_fluctuation", "equivalent_angle",
        "crosspiece_inertia_1", "crosspiece_inertia_2", "crosspiece_inertia_3",
        "bearing_radius", "rated_torque", "life_constant", "life_exponent", "life_min_angle",
        "life_rate_scale", "singularity_reach",
        *(f"joint_{k}_life_consumed{part}" for k in range(1, joints + 1)
          for part in ("", "_error")),
        *ahead_names(joints),
    )  # fmt: skip


def ahead_names(joints: int) -> tuple[str, ...]:
    """The step state's names of what life carries to the next step
    (`life_integral.step_integrals`' `ahead`): the last plain panel's start
    and end, then each joint's cubic on it."""
    return (
        "life_ahead_start", "life_ahead_end",
        *(f"joint_{k}_life_ahead_a{i}" for k in range(1, joints + 1) for i in range(4)),
    )  # fmt: skip


def takes_step(h: float, parameters_valid: bool, speed: float, acceleration: float,
               load: float) -> bool:  # fmt: skip
    """Whether the step is taken here; otherwise the model's checks name the
    refusal. NaN fails every comparison, so a NaN anywhere is never taken here."""
    return (
        sound_step(h, parameters_valid)
        and abs(speed) <= SPEED_LIMIT
        and abs(acceleration) <= _ACCELERATION_LIMIT
        and abs(load) <= _LOAD_LIMIT
        and shaft_moves(h, speed, acceleration, SPEED_LIMIT)
    )


def joint_torques(forward, backward, input_speed):
    """(T_1, w_0, ..., T_N, w_(N-1)): each joint's torque and its input
    shaft's speed, from `chain_forward`'s and `chain_backward`'s values and
    the input shaft's speed w_0 (`step_integrals`' torques)."""
    torques = (backward[0], input_speed)
    for k in range(1, len(backward) // 2):
        torques = torques + (backward[2 * k], forward[CHAIN_FIELDS * (k - 1) + SPEED])
    return torques


def chain_torque(t, step):
    """Every joint's (T_k, input shaft speed) t s into the step
    (`_STEP_HEAD`), `joint_torques`: the chain at that instant under the held
    load, the input shaft at constant acceleration."""
    speed, acceleration = step[2:4]  # `chain_at`'s head, then the load
    tail = step[_STEP_HEAD:]
    layout = step_layout(tail)
    forward = chain_at(t, step, layout, tail[len(layout) :])
    load = chain_backward(forward, layout, step[_STEP_HEAD - 1])
    return joint_torques(forward, load, speed + acceleration * t)


def chain_at(t, step, layout, trig):
    """The chain's load-free pass at a life node (`node_forward`) t s into the
    step: `step` starts with the input angle's fraction and error, the input
    speed and acceleration at the step's start and the cross's inertias;
    `trig` is `node_trig`'s (`step_layout`'s tail)."""
    fraction, error, speed, acceleration, I1, I2, I3 = step[:7]
    return node_forward(
        fraction, error + t * (speed + 0.5 * acceleration * t), speed + acceleration * t,
        acceleration, layout, trig, I1, I2, I3,
    )  # fmt: skip


def step_layout(tail):
    """The layout in the tail of a `chain_damages` step, after its head:
    `node_trig`'s sines and cosines follow it."""
    return tail[: LAYOUT_FIELDS * (len(tail) // _JOINT_FIELDS)]


def fixed_by_layout(layout) -> tuple:
    """What the step takes from the layout alone: `node_trig`'s sines and
    cosines and the singularities' reach at the largest bend (`chain_damages`),
    computed when the model starts."""
    peak = max(layout[k] for k in range(WORKING_ANGLE, len(layout), LAYOUT_FIELDS))
    return node_trig(layout), singularity_reach(peak)


def chain_damages(rule, h, torques_at, fraction, error, speed, acceleration, crosspiece, load,
                  layout, trig, reach, ahead):  # fmt: skip
    """Each joint's Miner damage over a step of `h` s from the input angle's
    `fraction` (+ `error`), the input shaft at `speed` and constant
    `acceleration`: `torques_at(t, step)` gives every joint's (T_k, input
    shaft speed), step = (fraction, error, speed, acceleration, the cross's
    inertias, *`load`) + layout + `trig`, its sines and cosines (`node_trig`);
    `load` the held load (`chain_torque`) or the
    parameters of a load that follows the motion. The joints share the nodes
    (`step_integrals`) and `reach`, the singularities' at the largest working
    angle (`fixed_by_layout`); the damages are followed by the `ahead` the
    next step takes (`ahead` this one's)."""
    bends = ()
    for k in range(len(layout) // LAYOUT_FIELDS):
        bends = bends + (layout[LAYOUT_FIELDS * k + WORKING_ANGLE],)
    step = (fraction, error, speed, acceleration, *crosspiece, *load) + layout + trig
    integrals = step_integrals(
        torques_at, step, h, speed, acceleration, bends, 0.0, 0.0, rule.min_angle, rule.exponent,
        reach, ahead,
    )  # fmt: skip
    scale = rule.scale / 3600.0
    damages = ()
    for k in range(len(bends)):
        damages = damages + (scale * integrals[k],)
    return damages + integrals[len(bends) :]


def sums_added(sums, damages):
    """Each joint's Miner's sum (total, error after each other) plus its
    damage, compensated."""
    added = ()
    for k in range(len(damages)):
        total, total_error = sums[2 * k], sums[2 * k + 1]
        if damages[k] != 0.0:
            total, total_error = compensated_add(total, total_error, damages[k])
        added = added + (total, total_error)
    return added


def propshaft_outputs(angle, speed, acceleration, load, layout, trig, shifts, critical_speeds,
                      fixed, I1, I2, I3, rule, radius, sums):  # fmt: skip
    """The outputs at input angle `angle` (`Turns`), in the table's order (`trig`
    the layout's `node_trig`): every shaft's
    angle (`shifts` put it on its branch), speed and acceleration, the input
    torque and energy, the `fixed` geometry outputs, each tube's speed over its
    critical speed, each joint's bearing forces, life rate and Miner's sum
    (`sums`: total and error per joint)."""
    fraction, error = angle[1], angle[2]
    values = chain_values(math, fraction, error, speed, acceleration, layout, trig, I1, I2, I3,
                          load)  # fmt: skip
    start = angle_value(angle)
    outputs = (start,)
    for k in range(len(shifts)):
        offset = values[CHAIN_FIELDS * k]
        outputs = outputs + (start + (offset - shifts[k]),)
        outputs = outputs + values[CHAIN_FIELDS * k + SPEED : CHAIN_FIELDS * k + ACCELERATION + 1]
    outputs = outputs + values[-2:]
    for k in range(len(shifts)):
        outputs = outputs + (layout[LAYOUT_FIELDS * k + WORKING_ANGLE],)
    outputs = outputs + fixed
    for k in range(len(critical_speeds)):
        outputs = outputs + (abs(values[CHAIN_FIELDS * k + SPEED]) / critical_speeds[k],)
    w, a = speed, acceleration
    for k in range(len(shifts)):
        joint = values[CHAIN_FIELDS * k : CHAIN_FIELDS * (k + 1)]
        beta = layout[LAYOUT_FIELDS * k + WORKING_ANGLE]
        sb, cb = trig[2 * k], trig[2 * k + 1]
        r = kernel_at(math, joint[PIN], sb, cb, w, a, 0.0, 0.0, I1, I2, I3, joint[LOAD], 1.0)
        outputs = outputs + life_outputs(
            rule, radius, sums[2 * k] + sums[2 * k + 1], joint[TORQUE], r[_INPUT_MOMENT],
            r[_OUTPUT_MOMENT], joint[LOAD], w, beta,
        )  # fmt: skip
        w, a = joint[SPEED], joint[ACCELERATION]
    return outputs


def propshaft_advanced(h, angle, parameters_valid, layout, trig, shifts, critical_speeds, fixed,
                       crosspiece, life, reach, sums, ahead, speed, acceleration,
                       load):  # fmt: skip
    """A step `takes_step` takes, of `h` s with the input shaft at constant
    acceleration and the load held: the state (`state_names`), the inputs
    after the step and the outputs. Each joint's Miner's sum gains its damage
    (from the values before the step), compensated."""
    fraction, error = angle[1], angle[2]
    I1, I2, I3 = crosspiece
    radius, rated_torque, life_constant, life_exponent, min_angle, scale = life
    rule = LifeRule(rated_torque, life_constant, life_exponent, min_angle, scale)
    end_speed = speed + acceleration * h
    end = advanced(angle, h * (speed + 0.5 * acceleration * h))
    damages = chain_damages(rule, h, chain_torque, fraction, error, speed, acceleration,
                            crosspiece, (load,), layout, trig, reach, ahead)  # fmt: skip
    added = sums_added(sums, damages[: len(shifts)])
    outputs = propshaft_outputs(
        end, end_speed, acceleration, load, layout, trig, shifts, critical_speeds, fixed, I1, I2,
        I3, rule, radius, added,
    )  # fmt: skip
    state = end + (parameters_valid,) + layout + trig + shifts + critical_speeds + fixed
    state = state + crosspiece + life + (reach,) + added + damages[len(shifts) :]
    return state + (end_speed, acceleration, load) + outputs
