"""The joint as a stepped system: the state the FMU keeps between steps.

`CardanJoint` holds the inputs, parameters, the input angle (as exact
revolutions, see `revolutions`) and the time; `step` advances them exactly for
inputs that are polynomial over the step, or refuses the step with a message
and changes nothing; `outputs` evaluates the closed forms for the current
values. Pure Python: the FMU maps its variables onto this object.
"""

from operator import itemgetter

from .. import variables as table
# The kernel itself: the FMU's once-per-step call on floats skips the array dispatch.
from .response import JointResponse
from .response import _response as joint_response_kernel
from . import limits
from .revolutions import RevolutionAngle, advance, split_angle

def _ranges(names, *excluded):
    return limits.ranges(table, names, *excluded)


# The bend angle's own limit is the max_bend_angle parameter, checked apart.
_INPUT_RANGES = _ranges(table.INPUTS, "bend_angle")
_PARAMETER_RANGES = _ranges(table.PARAMETERS, "max_bend_angle")
# The fast path of `input_problem` checks |x| <= max, so the ranges must be symmetric.
assert all(low == -high for _, low, high, _ in _INPUT_RANGES), "input ranges must be symmetric"
_SPEED_LIMIT = table.BY_NAME["input_speed"].max
_ACCELERATION_LIMIT = table.BY_NAME["input_acceleration"].max
_RATE_LIMIT = table.BY_NAME["bend_angle_rate"].max
_BEND_ACCELERATION_LIMIT = table.BY_NAME["bend_angle_acceleration"].max
_LOAD_LIMIT = table.BY_NAME["load_torque"].max
_MAX_INCREMENT = 1e15
_FROM_RESPONSE = itemgetter(*(JointResponse._fields.index(name) for name in table.OUTPUTS[2:]))


class CardanJoint:
    def __init__(self, **values):
        unknown = set(values) - set(table.INPUTS) - set(table.PARAMETERS)
        if unknown:
            raise TypeError(f"unknown joint variable(s): {', '.join(sorted(unknown))}")
        for name, value in {**table.start_values(), **values}.items():
            setattr(self, name, float(value))
        self.start(0.0)

    # --- set-up ------------------------------------------------------------

    def start(self, time: float) -> None:
        """Put the input angle at `input_angle_start` and the clock at `time`.

        Parameters are fixed from here on (as in FMI): they are checked here,
        once, and a change takes effect at the next `start`.
        """
        self.time = float(time)
        self.parameter_fault = self.parameter_problem()     # fixed until the next start
        valid = not self.parameter_fault
        self._angle = split_angle(self.input_angle_start if valid else 0.0)
        # The phase is reduced to whole turns plus a fraction too, so a large or
        # negative phase costs no precision; its turns enter the quaternion's sign.
        self._phase = split_angle(self.yoke_phase if valid else 0.0)

    def _bad_values(self, kind, names, ranges):
        """(name, explanation) of each of `names` not finite or outside its range."""
        return limits.bad_values(kind, self, names, ranges)

    def _value_problem(self, kind, names, ranges):
        """The first bad value, explained, or None."""
        return limits.first_problem(kind, self, names, ranges)

    def parameter_problem(self):
        """Why the parameters cannot run, or None."""
        problem = self._value_problem("parameter", table.PARAMETERS, _PARAMETER_RANGES)
        if problem:
            return problem
        guard = self.max_bend_angle
        if not 0.0 < guard < table.HALF_PI:
            return (f"parameter max_bend_angle = {guard!r} rad ({guard * table.DEG:.6g} deg) "
                    f"must lie strictly between 0 and pi/2 (90 deg, where the joint locks)")
        return None

    # --- stepping ----------------------------------------------------------

    def input_problem(self, step_size: float = 0.0):
        """Why the inputs cannot be used over [time, time + step_size], or None."""
        # Fast path for the common case, once per FMU step: every range at once and
        # the bend angle at both ends of the step. NaN fails every comparison, so
        # it always takes the slow path, which names the first problem.
        beta, rate, acc = self.bend_angle, self.bend_angle_rate, self.bend_angle_acceleration
        guard = self.max_bend_angle
        if (abs(self.input_speed) <= _SPEED_LIMIT
                and abs(self.input_acceleration) <= _ACCELERATION_LIMIT
                and abs(rate) <= _RATE_LIMIT and abs(acc) <= _BEND_ACCELERATION_LIMIT
                and abs(self.load_torque) <= _LOAD_LIMIT and abs(beta) < guard
                and abs(beta + step_size * (rate + 0.5 * acc * step_size)) < guard
                and (rate * acc >= 0.0 or -rate / acc >= step_size)):
            return None
        return self._explain_input_problem(step_size)

    def _explain_input_problem(self, step_size):
        problem = self._value_problem("input", table.INPUTS, _INPUT_RANGES)
        if problem:
            return problem
        guard = self.max_bend_angle
        worst_time, worst = self._largest_bend(step_size)
        if abs(worst) >= guard:
            where = ("" if worst_time == 0.0 else
                     f" (reached {worst_time:.6g} s into the step through bend_angle_rate"
                     f" = {self.bend_angle_rate!r} rad/s and bend_angle_acceleration"
                     f" = {self.bend_angle_acceleration!r} rad/s2)")
            return (f"input bend_angle = {worst!r} rad ({worst * table.DEG:.6g} deg){where}"
                    f" is not below the limit max_bend_angle = {guard!r} rad"
                    f" ({guard * table.DEG:.6g} deg)")
        return None

    def invalid_inputs(self) -> set:
        """Names of the inputs unusable at this instant (non-finite, out of range,
        bend angle at or beyond the guard)."""
        invalid = {name for name, _ in self._bad_values("input", table.INPUTS, _INPUT_RANGES)}
        if not abs(self.bend_angle) < self.max_bend_angle:
            invalid.add("bend_angle")
        return invalid

    def _largest_bend(self, step_size):
        """(time into the step, bend angle) of the largest |bend angle| over the step."""
        beta, rate, acc = self.bend_angle, self.bend_angle_rate, self.bend_angle_acceleration
        candidates = [(0.0, beta)]
        if step_size > 0.0:
            candidates.append((step_size, beta + step_size * (rate + 0.5 * acc * step_size)))
            if acc != 0.0 and 0.0 < -rate / acc < step_size:
                vertex = -rate / acc
                candidates.append((vertex, beta + vertex * (rate + 0.5 * acc * vertex)))
        return max(candidates, key=lambda c: abs(c[1]))

    def step_problem(self, step_size: float):
        return (limits.step_size_problem(step_size) or self.parameter_fault
                or self.input_problem(step_size))

    def step(self, step_size: float):
        """Advance by `step_size`; return None, or the reason the step was refused
        (then nothing has changed)."""
        problem = self.step_problem(step_size)
        if problem:
            return problem
        h = step_size
        speed, acceleration = self.input_speed, self.input_acceleration
        increment = h * (speed + 0.5 * acceleration * h)
        # Beyond 1e15 rad a float has no fractional digits left: the pin's position
        # after such a step is undefined, and the exact turn arithmetic would overflow.
        if not (abs(increment) <= _MAX_INCREMENT and abs(speed + acceleration * h) <= _SPEED_LIMIT):
            return (f"input_speed = {speed!r} rad/s with input_acceleration = {acceleration!r} "
                    f"rad/s2 over a step of {h!r} s overflows: the input angle would advance by "
                    f"{increment!r} rad (limit {_MAX_INCREMENT!r} rad per step) and the speed "
                    f"reach {speed + acceleration * h!r} rad/s (limit {_SPEED_LIMIT!r} rad/s)")
        self._angle = advance(self._angle, increment)
        self.input_speed = speed + acceleration * h
        rate, bend_acceleration = self.bend_angle_rate, self.bend_angle_acceleration
        self.bend_angle += h * (rate + 0.5 * bend_acceleration * h)
        self.bend_angle_rate = rate + bend_acceleration * h
        self.time += h
        return None

    # --- outputs -----------------------------------------------------------

    @property
    def input_angle(self) -> float:
        return float(self._angle)

    def response(self) -> JointResponse:
        angle, phase = self._angle, self._phase
        psi = angle.fraction + (phase.fraction + (angle.fraction_error + phase.fraction_error))
        sign = -1.0 if (angle.turns + phase.turns) & 1 else 1.0
        return joint_response_kernel(
            psi, self.bend_angle, self.input_speed, self.input_acceleration,
            self.bend_angle_rate, self.bend_angle_acceleration, self.crosspiece_inertia_1,
            self.crosspiece_inertia_2, self.crosspiece_inertia_3, self.load_torque, sign)

    def outputs(self) -> tuple:
        """Values of `variables.OUTPUTS`, in order; raises nothing for valid inputs."""
        r = self.response()
        input_angle = float(self._angle)
        # Two roundings at most: within one ulp of gamma2 however many turns.
        return (input_angle, input_angle + r[0]) + _FROM_RESPONSE(r)

    # --- state -------------------------------------------------------------

    def state(self) -> dict:
        """Everything that defines the joint, as JSON-serialisable values."""
        values = {name: getattr(self, name) for name in table.INPUTS + table.PARAMETERS}
        a = self._angle
        values.update(time=self.time, turns=a.turns, fraction=a.fraction,
                      fraction_error=a.fraction_error)
        return values

    def restore(self, state: dict) -> None:
        """Take a `state()`; all or nothing (a malformed state raises and changes nothing)."""
        values = {name: float(state[name]) for name in table.INPUTS + table.PARAMETERS}
        time = float(state["time"])
        angle = RevolutionAngle(int(state["turns"]), float(state["fraction"]),
                                float(state["fraction_error"]))
        for name, value in values.items():
            setattr(self, name, value)
        self.start(time)
        self._angle = angle
