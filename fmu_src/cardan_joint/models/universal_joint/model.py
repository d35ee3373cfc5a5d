"""The joint as a stepped system: the state the FMU keeps between steps.

`CardanJoint` holds the inputs, parameters, the input angle (as exact
revolutions, see `revolutions`) and the time; `step` advances them exactly for
inputs that are polynomial over the step, or refuses the step and changes
nothing, returning a `Refusal` (variable, value, limit, time, reason code);
`outputs` evaluates the closed forms for the current values. Pure Python: the
FMU maps its variables onto this object.
"""

import math

from ...framework.refusal import Refusal
from ...framework.stepped import ShaftModel
from ...framework.values import Table, angle_limit_problem, set_start_values
from ...framework.written_step import WrittenStep
from ...physics.response import JointResponse, kernel
from ...physics.revolutions import split_turns
from ...variable_schema import Variable
from . import variables as table
from .life import JointLife
from .limits import (
    INPUT_RANGES,
    PARAMETER_RANGES,
    PARAMETER_RANGES_WITHOUT_LIFE,
    SPEED_LIMIT,
    fits,
)
from .refusals import JointReason
from .step import ANGLE, STATE, joint_life_step, joint_outputs, joint_step


class CardanJoint(WrittenStep, JointLife, ShaftModel):
    table: Table = table
    _input_ranges = INPUT_RANGES
    _parameter_ranges = PARAMETER_RANGES
    _speed_limit = SPEED_LIMIT

    # Inputs and parameters (`variables.INPUTS`, `variables.PARAMETERS`): __init__
    # sets each from the table, so the names here must be the table's.
    input_speed: float
    input_acceleration: float
    bend_angle: float
    bend_angle_rate: float
    bend_angle_acceleration: float
    load_torque: float
    yoke_phase: float
    input_angle_start: float
    crosspiece_inertia_1: float
    crosspiece_inertia_2: float
    crosspiece_inertia_3: float
    max_bend_angle: float

    def __init__(self, life: bool = True, **values: float) -> None:
        self.life = life
        if not life:
            self.table = table.WITHOUT_LIFE
            self._parameter_ranges = PARAMETER_RANGES_WITHOUT_LIFE
        set_start_values(self, self.table, values, "joint")
        self.start(0.0)

    # --- set-up ------------------------------------------------------------

    def start(self, time: float) -> None:
        """Put the input angle at `input_angle_start` and the clock at `time`.

        Parameters are fixed from here on (as in FMI): they are checked here,
        once, and a change takes effect at the next `start`.
        """
        self.time = float(time)
        self.parameter_fault = self.parameter_problem()  # fixed until the next start
        valid = not self.parameter_fault
        self._angle = split_turns(self.input_angle_start if valid else 0.0)
        # The phase is reduced to whole turns plus a fraction too, so a large or
        # negative phase costs no precision; its turns enter the quaternion's sign.
        self._phase = split_turns(self.yoke_phase if valid else 0.0)
        self._start_life()

    def _non_finite_limit(self, name: str, variable: Variable) -> float:
        # The bend angle's limit is the max_bend_angle parameter, not its table range.
        if name == "bend_angle":
            return self.max_bend_angle
        return super()._non_finite_limit(name, variable)

    def parameter_problem(self) -> Refusal | None:
        """The Refusal that keeps the parameters from running, or None."""
        problem = self._value_problem(self.table.PARAMETERS, self._parameter_ranges)
        if problem:
            return problem
        return angle_limit_problem(
            JointReason.BEND_GUARD, "max_bend_angle", self.max_bend_angle, self.time
        )

    # --- stepping ----------------------------------------------------------

    def input_problem(self, step_size: float = 0.0) -> Refusal | None:
        """The Refusal of the inputs over [time, time + step_size], or None."""
        # Fast path for the common case, once per FMU step: every range at once and
        # the bend angle at both ends of the step. NaN fails every comparison, so
        # it always takes the slow path, which names the first problem.
        speed, acceleration, beta, rate, acc, load = self.inputs()
        if fits(speed, acceleration, beta, rate, acc, load, self.max_bend_angle, step_size):
            return None
        return self._explain_input_problem(step_size)

    def _explain_input_problem(self, step_size: float) -> Refusal | None:
        problem = self._value_problem(self.table.INPUTS, INPUT_RANGES)
        if problem:
            return problem
        guard = self.max_bend_angle
        reason, after, worst = self._largest_bend(step_size)
        if abs(worst) >= guard:
            details = (
                {}
                if reason is JointReason.BEND_ANGLE
                else {
                    "after": after,
                    "bend_angle_rate": self.bend_angle_rate,
                    "bend_angle_acceleration": self.bend_angle_acceleration,
                }
            )
            return Refusal(reason, "bend_angle", worst, guard, self.time, "rad", details)
        return None

    def invalid_inputs(self) -> set:
        """Names of the inputs unusable at this instant (non-finite, out of range,
        bend angle at or beyond the guard)."""
        invalid = super().invalid_inputs()
        if not abs(self.bend_angle) < self.max_bend_angle:
            invalid.add("bend_angle")
        return invalid

    def _largest_bend(self, step_size):
        """(JointReason, time into the step, bend angle) of the largest |bend angle|
        over the step."""
        beta, rate, acc = self.bend_angle, self.bend_angle_rate, self.bend_angle_acceleration
        candidates = [(JointReason.BEND_ANGLE, 0.0, beta)]
        if step_size > 0.0:
            candidates.append(
                (
                    JointReason.BEND_AT_STEP_END,
                    step_size,
                    beta + step_size * (rate + 0.5 * acc * step_size),
                )
            )
            if acc != 0.0 and 0.0 < -rate / acc < step_size:
                vertex = -rate / acc
                candidates.append(
                    (
                        JointReason.BEND_PEAK_IN_STEP,
                        vertex,
                        beta + vertex * (rate + 0.5 * acc * vertex),
                    )
                )
        return max(candidates, key=lambda c: abs(c[2]))

    def _advance(self, h: float) -> Refusal | None:
        """The input shaft (`ShaftModel`), then the bend angle, exact for its constant
        acceleration over the step, and the life consumed (docs/life.md); a
        refusal changes nothing."""
        # The damage's start values, taken before the step (life on only: see `run`).
        start = self._life_start() if self.life else None
        problem = super()._advance(h)
        if problem:
            return problem
        rate, bend_acceleration = self.bend_angle_rate, self.bend_angle_acceleration
        self.bend_angle += h * (rate + 0.5 * bend_acceleration * h)
        self.bend_angle_rate = rate + bend_acceleration * h
        if start is not None:
            self._add_damage(h, start)
        return None

    # --- the FMU's step ------------------------------------------------------

    def written_step(self):
        """The step (`WrittenStep.run`): `step.joint_step`, `joint_life_step` with
        life on, the definition the FMU's C runtime is generated from; a step it
        does not take goes through the generic checks, which name the refusal."""
        return joint_life_step if self.life else joint_step

    def step_state(self) -> tuple:
        """What the step advances beside the inputs: `step.STATE`'s values
        (`LIFE_STATE`'s with life on)."""
        angle = (*self._angle, *self._phase, self.parameter_fault is None)
        if not self.life:
            return angle
        return (*angle, self.life_consumed, self.life_consumed_error, self._life_rule.scale)

    def set_step_state(self, state) -> None:
        """Take a state a generated step advanced (`step_state`'s values); only the
        angle and Miner's sum move over a step, the rest follows the parameters."""
        turns, fraction, fraction_error = state[:ANGLE]
        self._angle = (int(turns), float(fraction), float(fraction_error))
        if self.life:
            consumed, error = state[len(STATE) : len(STATE) + 2]
            self.life_consumed, self.life_consumed_error = float(consumed), float(error)

    # --- outputs -----------------------------------------------------------

    def response(self) -> JointResponse:
        """Every closed form at the current state (the one evaluation of a step)."""
        turns, fraction, error = self._angle
        phase_turns, phase_fraction, phase_error = self._phase
        return JointResponse._make(
            kernel(
                math,
                fraction + (phase_fraction + (error + phase_error)),
                self.bend_angle,
                self.input_speed,
                self.input_acceleration,
                self.bend_angle_rate,
                self.bend_angle_acceleration,
                self.crosspiece_inertia_1,
                self.crosspiece_inertia_2,
                self.crosspiece_inertia_3,
                self.load_torque,
                -1.0 if (turns + phase_turns) & 1 else 1.0,
            )
        )

    def outputs(self) -> tuple:
        """Values of `variables.OUTPUTS`, in order; raises nothing for valid inputs."""
        return self._outputs(
            self._angle,
            self.bend_angle,
            self.input_speed,
            self.input_acceleration,
            self.bend_angle_rate,
            self.bend_angle_acceleration,
            self.load_torque,
        )

    def _outputs(self, angle, beta, speed, acceleration, rate, bend_acceleration, load) -> tuple:
        values = joint_outputs(
            angle, self._phase, beta, speed, acceleration, rate, bend_acceleration, load,
            self.crosspiece_inertia_1, self.crosspiece_inertia_2, self.crosspiece_inertia_3,
        )  # fmt: skip
        # The kernel's fields follow the two angles (`step.KINEMATIC_OUTPUTS`).
        return self._with_life(values, values[2:], load, speed, beta) if self.life else values
