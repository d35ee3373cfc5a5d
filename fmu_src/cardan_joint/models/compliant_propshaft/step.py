"""The CompliantPropshaft's step, written once: the definition
`CompliantPropshaft.run` runs and the build translates into the FMU's C
runtime (docs/codegen.md), so both give the same bits. The propshaft's step
(`propshaft.step`) with the spring-damper layer's functions
(`compliant_joint.step`) at its output: the chain steps with no load (its
kinematics do not depend on it); its joints' life integrates the chain under
the spring's moving torque (`spring_chain_torque`: the chain's load-free
pass gives the spring's torque, which its backward pass carries).
"""

import math

from ...physics.life import LifeRule
from ...physics.revolutions import advanced, angle_value
from ..compliant_joint.step import spring_load, spring_outputs, spring_takes_step, twist_change
from ..propshaft.chain import (
    CHAIN_FIELDS,
    OFFSET,
    SPEED,
    chain_backward,
    chain_values,
)
from ..propshaft.step import (
    chain_at,
    chain_damages,
    joint_torques,
    propshaft_outputs,
    state_names,
    step_layout,
    sums_added,
    takes_step,
)

# The spring's part of the step state, after the propshaft's (`state_names`).
SPRING_STATE = ("lag", "stiffness", "damping")
# `spring_chain_torque`'s step: `chain_torque`'s head without the load, then
# the spring's (the last shaft's branch shift, lag, output shaft's speed and
# acceleration, k, c), then the layout and its sines and cosines (`node_trig`).
_STEP_HEAD = 13


def compliant_state_names(joints: int) -> tuple[str, ...]:
    """The step state's names: the propshaft's, then the spring's."""
    return (*state_names(joints), *SPRING_STATE)


def spring_chain_torque(t, step):
    """Every joint's (T_k, input shaft speed) t s into the step under the
    spring (`joint_torques`): the chain's load-free pass gives the
    kinematics the spring's torque needs (the last shaft's offset and
    speed), its backward pass the torques under that load."""
    speed, acceleration = step[2:4]  # `chain_at`'s head, then the spring's
    shift, lag, output_speed, output_acceleration, stiffness, damping = step[7:_STEP_HEAD]
    tail = step[_STEP_HEAD:]
    layout = step_layout(tail)
    forward = chain_at(t, step, layout, tail[len(layout) :])
    # The last joint's output shaft: its offset and speed.
    load = spring_load(
        t, forward[len(forward) - 1 - CHAIN_FIELDS + OFFSET] - shift,
        forward[len(forward) - 1 - CHAIN_FIELDS + SPEED], lag, speed, acceleration,
        output_speed, output_acceleration, stiffness, damping,
    )  # fmt: skip
    return joint_torques(forward, chain_backward(forward, layout, load), speed + acceleration * t)


def compliant_takes_step(h: float, parameters_valid: bool, speed: float, acceleration: float,
                         output_speed: float, output_acceleration: float) -> bool:  # fmt: skip
    """Whether the step is taken here (the chain's inputs with no load, the
    spring's); otherwise the model's checks name the refusal."""
    change = twist_change(h, speed, acceleration, output_speed, output_acceleration)
    return takes_step(h, parameters_valid, speed, acceleration, 0.0) and spring_takes_step(
        output_speed, output_acceleration, change
    )


def compliant_propshaft_advanced(h, angle, parameters_valid: bool, layout, trig, shifts,
                                 critical_speeds, fixed, crosspiece, life, reach, sums, ahead,
                                 spring, speed, acceleration, output_speed,
                                 output_acceleration):  # fmt: skip
    """A step `compliant_takes_step` takes, of `h` s: the state
    (`compliant_state_names`), the inputs after the step and the outputs. The
    spring's torque at the step's end is the chain's load for the outputs;
    over the step, the load each joint's Miner's sum integrates (from the
    values before the step)."""
    lag, stiffness, damping = spring
    change = twist_change(h, speed, acceleration, output_speed, output_acceleration)
    I1, I2, I3 = crosspiece
    radius, rated_torque, life_constant, life_exponent, min_angle, scale = life
    rule = LifeRule(rated_torque, life_constant, life_exponent, min_angle, scale)
    load = (shifts[len(shifts) - 1], lag, output_speed, output_acceleration, stiffness, damping)
    damages = chain_damages(rule, h, spring_chain_torque, angle[1], angle[2], speed, acceleration,
                            crosspiece, load, layout, trig, reach, ahead)  # fmt: skip
    added = sums_added(sums, damages[: len(shifts)])
    end_speed = speed + acceleration * h
    end = advanced(angle, h * (speed + 0.5 * acceleration * h))
    end_lag = lag + change
    end_output_speed = output_speed + output_acceleration * h
    free = chain_values(math, end[1], end[2], end_speed, acceleration, layout, trig, I1, I2, I3,
                        0.0)  # fmt: skip
    # The last joint's values in the chain's: its output shaft's offset and speed.
    offset = free[CHAIN_FIELDS * (len(shifts) - 1) + OFFSET] - shifts[len(shifts) - 1]
    spring_values = spring_outputs(
        angle_value(end), end_lag, offset, free[CHAIN_FIELDS * (len(shifts) - 1) + SPEED],
        end_output_speed, stiffness, damping,
    )  # fmt: skip
    rigid = propshaft_outputs(
        end, end_speed, acceleration, spring_values[3], layout, trig, shifts, critical_speeds,
        fixed, I1, I2, I3, rule, radius, added,
    )  # fmt: skip
    # The rigid outputs but the input angle and the last shaft's (the spring's own).
    passed = rigid[1 : 3 * len(shifts) - 2] + rigid[3 * len(shifts) + 1 :]
    state = end + (parameters_valid,) + layout + trig + shifts + critical_speeds + fixed
    state = state + crosspiece + life + (reach,) + added + damages[len(shifts) :]
    state = state + (end_lag, stiffness, damping)
    moved = (end_speed, acceleration, end_output_speed, output_acceleration)
    return state + moved + spring_values + passed
