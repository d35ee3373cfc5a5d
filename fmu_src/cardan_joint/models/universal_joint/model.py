"""The joint as a stepped system: the state the FMU keeps between steps.

`CardanJoint` holds the inputs, parameters, the input angle (as exact
revolutions, see `revolutions`) and the time; `step` advances them exactly for
inputs that are polynomial over the step, or refuses the step and changes
nothing, returning a `Refusal` (variable, value, limit, time, reason code);
`outputs` evaluates the closed forms for the current values. Pure Python: the
FMU maps its variables onto this object.
"""

import math
from operator import itemgetter
from typing import Any

from ...physics.life import compensated_add, life_outputs, rule_of, step_damage
from ...physics.refusal import Reason, Refusal

# The kernel itself: the FMU's once-per-step call on floats skips the array dispatch.
from ...physics.response import JointResponse
from ...physics.response import _response as joint_response_kernel
from ...physics.revolutions import split_angle
from ...physics.stepped import ShaftModel
from ...physics.values import Table, angle_limit_problem, bounds, set_start_values, value_ranges
from ...variable_schema import Variable
from . import variables as table


def _ranges(names, *excluded):
    return value_ranges(table.BY_NAME, names, *excluded)


# The bend angle's own limit is the max_bend_angle parameter, checked apart.
_INPUT_RANGES = _ranges(table.INPUTS, "bend_angle")
_PARAMETER_RANGES = _ranges(table.PARAMETERS, "max_bend_angle")
_PARAMETER_RANGES_WITHOUT_LIFE = _ranges(table.WITHOUT_LIFE.PARAMETERS, "max_bend_angle")
# The fast path of `input_problem` checks |x| <= max, so the ranges must be symmetric.
# (A ranged input it does not name fails tests/test_guards.py, which takes every
# ranged input from the table.)
assert all(low == -high for _, low, high, _ in _INPUT_RANGES), "input ranges must be symmetric"
_SPEED_LIMIT = bounds(table.BY_NAME["input_speed"])[1]
_ACCELERATION_LIMIT = bounds(table.BY_NAME["input_acceleration"])[1]
_RATE_LIMIT = bounds(table.BY_NAME["bend_angle_rate"])[1]
_BEND_ACCELERATION_LIMIT = bounds(table.BY_NAME["bend_angle_acceleration"])[1]
_LOAD_LIMIT = bounds(table.BY_NAME["load_torque"])[1]
_FROM_RESPONSE = itemgetter(
    *(JointResponse._fields.index(name) for name in table.WITHOUT_LIFE.OUTPUTS[2:])
)


class CardanJoint(ShaftModel):
    table: Table = table
    _input_ranges = _INPUT_RANGES
    _parameter_ranges = _PARAMETER_RANGES
    _speed_limit = _SPEED_LIMIT

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
    # Bearing and life parameters (build setting `life`, docs/life.md).
    bearing_radius: float
    rated_torque: float
    life_constant: float
    life_exponent: float
    life_min_angle: float

    def __init__(self, life: bool = True, **values: float) -> None:
        self.life = life
        if life:  # Miner's sum, compensated: the model's own state
            self._STATE = ("life_consumed", "life_consumed_error")
        else:
            self.table = table.WITHOUT_LIFE
            self._parameter_ranges = _PARAMETER_RANGES_WITHOUT_LIFE
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
        self._angle = split_angle(self.input_angle_start if valid else 0.0)
        # The phase is reduced to whole turns plus a fraction too, so a large or
        # negative phase costs no precision; its turns enter the quaternion's sign.
        self._phase = split_angle(self.yoke_phase if valid else 0.0)
        if self.life:
            self._life_rule = rule_of(self)
            self.life_consumed = self.life_consumed_error = 0.0

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
            Reason.BEND_GUARD, "max_bend_angle", self.max_bend_angle, self.time
        )

    # --- stepping ----------------------------------------------------------

    def input_problem(self, step_size: float = 0.0) -> Refusal | None:
        """The Refusal of the inputs over [time, time + step_size], or None."""
        # Fast path for the common case, once per FMU step: every range at once and
        # the bend angle at both ends of the step. NaN fails every comparison, so
        # it always takes the slow path, which names the first problem.
        beta, rate, acc = self.bend_angle, self.bend_angle_rate, self.bend_angle_acceleration
        guard = self.max_bend_angle
        if (
            abs(self.input_speed) <= _SPEED_LIMIT
            and abs(self.input_acceleration) <= _ACCELERATION_LIMIT
            and abs(rate) <= _RATE_LIMIT
            and abs(acc) <= _BEND_ACCELERATION_LIMIT
            and abs(self.load_torque) <= _LOAD_LIMIT
            and abs(beta) < guard
            and abs(beta + step_size * (rate + 0.5 * acc * step_size)) < guard
            and (rate * acc >= 0.0 or -rate / acc >= step_size)
        ):
            return None
        return self._explain_input_problem(step_size)

    def _explain_input_problem(self, step_size: float) -> Refusal | None:
        problem = self._value_problem(self.table.INPUTS, _INPUT_RANGES)
        if problem:
            return problem
        guard = self.max_bend_angle
        reason, after, worst = self._largest_bend(step_size)
        if abs(worst) >= guard:
            details = (
                {}
                if reason is Reason.BEND_ANGLE
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
        """(Reason, time into the step, bend angle) of the largest |bend angle| over the step."""
        beta, rate, acc = self.bend_angle, self.bend_angle_rate, self.bend_angle_acceleration
        candidates = [(Reason.BEND_ANGLE, 0.0, beta)]
        if step_size > 0.0:
            candidates.append(
                (
                    Reason.BEND_AT_STEP_END,
                    step_size,
                    beta + step_size * (rate + 0.5 * acc * step_size),
                )
            )
            if acc != 0.0 and 0.0 < -rate / acc < step_size:
                vertex = -rate / acc
                candidates.append(
                    (Reason.BEND_PEAK_IN_STEP, vertex, beta + vertex * (rate + 0.5 * acc * vertex))
                )
        return max(candidates, key=lambda c: abs(c[2]))

    def _advance(self, h: float) -> Refusal | None:
        """The input shaft (`ShaftModel`), then the bend angle, exact for its constant
        acceleration over the step, and the life consumed (docs/life.md); a
        refusal changes nothing."""
        # The damage from the step's start values, once the shaft has taken the step.
        start = self._life_start() if self.life else None
        problem = super()._advance(h)
        if problem:
            return problem
        rate, bend_acceleration = self.bend_angle_rate, self.bend_angle_acceleration
        self.bend_angle += h * (rate + 0.5 * bend_acceleration * h)
        self.bend_angle_rate = rate + bend_acceleration * h
        damage = step_damage(self._life_rule, h, *start) if start else 0.0
        if damage:
            self.life_consumed, self.life_consumed_error = compensated_add(
                self.life_consumed, self.life_consumed_error, damage
            )
        return None

    def _psi(self) -> float:
        angle, phase = self._angle, self._phase
        return angle.fraction + (phase.fraction + (angle.fraction_error + phase.fraction_error))

    def _life_start(self) -> tuple[Any, ...]:
        """What the damage of the next step starts from (`life.step_damage`)."""
        return (
            self._psi(),
            self.bend_angle,
            self.input_speed,
            self.input_acceleration,
            self.bend_angle_rate,
            self.bend_angle_acceleration,
            (self.crosspiece_inertia_1, self.crosspiece_inertia_2, self.crosspiece_inertia_3),
            self.load_torque,
        )

    # --- outputs -----------------------------------------------------------

    def response(self) -> JointResponse:
        sign = -1.0 if (self._angle.turns + self._phase.turns) & 1 else 1.0
        return joint_response_kernel(
            self._psi(),
            self.bend_angle,
            self.input_speed,
            self.input_acceleration,
            self.bend_angle_rate,
            self.bend_angle_acceleration,
            self.crosspiece_inertia_1,
            self.crosspiece_inertia_2,
            self.crosspiece_inertia_3,
            self.load_torque,
            sign,
        )

    def outputs(self) -> tuple:
        """Values of `variables.OUTPUTS`, in order; raises nothing for valid inputs."""
        r = self.response()
        input_angle = float(self._angle)
        # Two roundings at most: within one ulp of gamma2 however many turns.
        values = (input_angle, input_angle + r[0]) + _FROM_RESPONSE(r)
        if not self.life:
            return values
        if self.parameter_fault:  # a zero radius or rated torque has no load or life
            return values + (math.nan, math.nan, math.nan, self.life_consumed)
        return values + life_outputs(
            self._life_rule,
            self.bearing_radius,
            self.life_consumed + self.life_consumed_error,
            r.input_torque,
            r.input_yoke_moment,
            r.output_yoke_moment,
            self.load_torque,
            self.input_speed,
            self.bend_angle,
        )
