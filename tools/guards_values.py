"""The mutation table's value guards (tools/guards.py): each input's and
parameter's finiteness and range, and the bend angle now, at the step's end and
at its peak inside the step, in the slow path and the fast path."""

from guards_base import (
    GUARDS,
    LIMITS,
    MODEL,
    SLAVE_GUARDS,
    STEPPED,
    VALUES,
    Mutation,
)

# guards_base put fmu_src on the path (the mutation run copies the tree, no install).
from cardan_joint.models.universal_joint import variables as table

FINITE_LOOP = (
    "        for name in names:\n            value = getattr(self, name)\n"
    "            if not math.isfinite(value):"
)
INPUT_RANGES = 'INPUT_RANGES = _ranges(table.INPUTS, "bend_angle")'
PARAMETER_RANGES = 'PARAMETER_RANGES = _ranges(table.PARAMETERS, "max_bend_angle")'
# Every input and parameter but the bend angle and its guard has a table range.
RANGED_INPUTS = tuple(n for n in table.INPUTS if n != "bend_angle")
RANGED_PARAMETERS = tuple(n for n in table.PARAMETERS if n != "max_bend_angle")
ALL_INPUTS = table.INPUTS
PARAMETERS = table.PARAMETERS
FAST_PATH = {
    "input_speed": "abs(speed) <= SPEED_LIMIT",
    "input_acceleration": "abs(acceleration) <= _ACCELERATION_LIMIT",
    "bend_angle_rate": "abs(rate) <= _RATE_LIMIT",
    "bend_angle_acceleration": "abs(acc) <= _BEND_ACCELERATION_LIMIT",
    "load_torque": "abs(load) <= _LOAD_LIMIT",
}
PEAK_TESTS = (GUARDS, SLAVE_GUARDS, "-k", "peak")


def _skip(name):
    return FINITE_LOOP.replace(
        "for name in names:", f"for name in [n for n in names if n != {name!r}]:"
    )


VALUE_MUTATIONS = (
    # Inputs: finiteness and range, each variable alone, in the slow path and the fast path.
    *(
        Mutation(
            f"input {n} finite", STEPPED, FINITE_LOOP, _skip(n), (GUARDS, "-k", "non_finite_input")
        )
        for n in ALL_INPUTS
    ),
    *(
        Mutation(
            f"input {n} range (slow path)",
            LIMITS,
            INPUT_RANGES,
            INPUT_RANGES.replace('"bend_angle"', f'"bend_angle", {n!r}'),
            (GUARDS, "-k", "input"),
        )
        for n in RANGED_INPUTS
    ),
    *(
        Mutation(
            f"input {n} range (fast path)", LIMITS, FAST_PATH[n], "True", (GUARDS, "-k", "input")
        )
        for n in RANGED_INPUTS
    ),
    Mutation(
        "inputs: any bad value (slow path)",
        MODEL,
        "self._value_problem(self.table.INPUTS, INPUT_RANGES)",
        "None",
        (GUARDS, "-k", "input"),
    ),
    # Parameters, checked once per start.
    *(
        Mutation(
            f"parameter {n} finite", STEPPED, FINITE_LOOP, _skip(n), (GUARDS, "-k", "parameter")
        )
        for n in PARAMETERS
    ),
    *(
        Mutation(
            f"parameter {n} range",
            LIMITS,
            PARAMETER_RANGES,
            PARAMETER_RANGES.replace('"max_bend_angle"', f'"max_bend_angle", {n!r}'),
            (GUARDS, "-k", "parameter"),
        )
        for n in RANGED_PARAMETERS
    ),
    Mutation(
        "parameter max_bend_angle / max_working_angle in (0, pi/2)",
        VALUES,
        "    if 0.0 < value < HALF_PI:\n        return None\n",
        "    if True:\n        return None\n",
        (GUARDS, "-k", "max_bend_angle"),
    ),
    Mutation(
        "bad parameters refuse every step",
        STEPPED,
        "if self.parameter_fault:\n            return self.parameter_fault.at(self.time)",
        "if False:\n            return self.parameter_fault.at(self.time)",
        (GUARDS, "-k", "parameter or max_bend_angle"),
    ),
    Mutation(
        "bad input_angle_start not used as the start angle",
        MODEL,
        "split_turns(self.input_angle_start if valid else 0.0)",
        "split_turns(self.input_angle_start)",
        (GUARDS, "-k", "parameter"),
    ),
    Mutation(
        "bad yoke_phase not used as the phase",
        MODEL,
        "split_turns(self.yoke_phase if valid else 0.0)",
        "split_turns(self.yoke_phase)",
        (GUARDS, "-k", "parameter"),
    ),
    Mutation(
        "bad life parameters not made into the rule the state carries",
        "fmu_src/cardan_joint/models/universal_joint/life.py",
        "self._life_rule = NO_RULE if fault else rule_of(self)",
        "self._life_rule = rule_of(self)",
        ("tests/unit/test_step_constants.py", "-k", "out_of_its_ranges"),
    ),
    # The bend angle: now, at the step's end, at the peak inside the step; both paths.
    Mutation(
        "bend angle now (fast path)",
        LIMITS,
        "and abs(beta) < guard",
        "and True",
        (GUARDS, "-k", "bend"),
    ),
    Mutation(
        "bend angle at step end (fast path)",
        LIMITS,
        "abs(beta + step_size * (rate + 0.5 * acc * step_size)) < guard",
        "True",
        (GUARDS, "-k", "bend"),
    ),
    Mutation(
        "bend peak inside the step (fast path)",
        LIMITS,
        "(rate * acc >= 0.0 or -rate / acc >= step_size)",
        "True",
        PEAK_TESTS,
    ),
    Mutation(
        "bend angle now (slow path)",
        MODEL,
        "candidates = [(JointReason.BEND_ANGLE, 0.0, beta)]",
        "candidates = [(JointReason.BEND_ANGLE, 0.0, 0.0)]",
        (GUARDS, "-k", "bend"),
    ),
    Mutation(
        "bend angle at step end (slow path)",
        MODEL,
        "                    JointReason.BEND_AT_STEP_END,\n"
        "                    step_size,\n"
        "                    beta + step_size * (rate + 0.5 * acc * step_size),\n",
        "                    JointReason.BEND_AT_STEP_END,\n                    step_size,\n"
        "                    beta,\n",
        (GUARDS, "-k", "bend"),
    ),
    Mutation(
        "bend peak inside the step (slow path)",
        MODEL,
        "if acc != 0.0 and 0.0 < -rate / acc < step_size:",
        "if False:",
        PEAK_TESTS,
    ),
    Mutation(
        "bend angle against max_bend_angle (slow path)",
        MODEL,
        "if abs(worst) >= guard:",
        "if False:",
        (GUARDS, "-k", "bend"),
    ),
    Mutation(
        "propshaft tube: inner diameter below the outer",
        "fmu_src/cardan_joint/models/propshaft/model.py",
        "if not inner < outer:",
        "if False:",
        ("tests/unit/test_propshaft_refusals.py", "-k", "wall"),
    ),
    Mutation(
        "bend angle marks its outputs invalid",
        MODEL,
        "if not abs(self.bend_angle) < self.max_bend_angle:",
        "if False:",
        (GUARDS, "-k", "bend"),
    ),
)
