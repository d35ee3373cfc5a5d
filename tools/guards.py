"""The guards the mutation run disables (tools/mutation.py): for each, the
text that is the guard in its file, what replaces it, and the tests that must
notice. tests/test_mutation_list.py checks that each target text occurs exactly
once, so a refactor cannot orphan a guard."""

import difflib
import sys
from dataclasses import dataclass
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "fmu_src"))
from cardan_joint.models.universal_joint import variables as table  # noqa: E402

COPIED = ("fmu_src", "tests", "build_fmu.py", "pyproject.toml", "README.md")
RESTORED = "        values = {name: float(state[name]) for name in self._saved_names()}\n"
MODEL = "fmu_src/cardan_joint/models/universal_joint/model.py"
VALUES = "fmu_src/cardan_joint/physics/values.py"
SLAVE = "fmu_src/cardan_joint/fmi/slave.py"
CORE = "fmu_src/cardan_joint/fmi/core.py"
FAST_STEP = "fmu_src/cardan_joint/fmi/fast_step.py"
GUARDS = "tests/test_guards.py"
SLAVE_GUARDS = "tests/test_slave_guards.py"
ROBUSTNESS = "tests/test_robustness.py"
COMPLIANT = "fmu_src/cardan_joint/models/compliant_joint/model.py"
COMPLIANT_TESTS = "tests/test_compliant_joint.py"
FAST_STEP_TESTS = "tests/test_fast_step.py"


@dataclass(frozen=True)
class Mutation:
    guard: str
    path: str
    target: str  # must occur exactly once in `path`
    replacement: str
    tests: tuple  # pytest arguments: the tests expected to catch it

    @property
    def what(self):
        """The changed lines only: `removed` -> `added`."""
        diff = list(difflib.ndiff(self.target.splitlines(), self.replacement.splitlines()))
        removed = " ".join(line[2:].strip() for line in diff if line.startswith("- "))
        added = " ".join(line[2:].strip() for line in diff if line.startswith("+ "))
        return f"`{removed}` -> `{added}`" if removed else f"insert `{added}`"


FINITE_LOOP = (
    "        for name in names:\n            value = getattr(self, name)\n"
    "            if not math.isfinite(value):"
)
INPUT_RANGES = '_INPUT_RANGES = _ranges(table.INPUTS, "bend_angle")'
PARAMETER_RANGES = '_PARAMETER_RANGES = _ranges(table.PARAMETERS, "max_bend_angle")'
# Every input and parameter but the bend angle and its guard has a table range.
RANGED_INPUTS = tuple(n for n in table.INPUTS if n != "bend_angle")
RANGED_PARAMETERS = tuple(n for n in table.PARAMETERS if n != "max_bend_angle")
ALL_INPUTS = table.INPUTS
PARAMETERS = table.PARAMETERS
FAST_PATH = {
    "input_speed": "abs(self.input_speed) <= _SPEED_LIMIT",
    "input_acceleration": "abs(self.input_acceleration) <= _ACCELERATION_LIMIT",
    "bend_angle_rate": "abs(rate) <= _RATE_LIMIT",
    "bend_angle_acceleration": "abs(acc) <= _BEND_ACCELERATION_LIMIT",
    "load_torque": "abs(self.load_torque) <= _LOAD_LIMIT",
}
PEAK_TESTS = (GUARDS, SLAVE_GUARDS, "-k", "peak")


def _skip(name):
    return FINITE_LOOP.replace(
        "for name in names:", f"for name in [n for n in names if n != {name!r}]:"
    )


MUTATIONS = (
    # Inputs: finiteness and range, each variable alone, in the slow path and the fast path.
    *(
        Mutation(
            f"input {n} finite", VALUES, FINITE_LOOP, _skip(n), (GUARDS, "-k", "non_finite_input")
        )
        for n in ALL_INPUTS
    ),
    *(
        Mutation(
            f"input {n} range (slow path)",
            MODEL,
            INPUT_RANGES,
            INPUT_RANGES.replace('"bend_angle"', f'"bend_angle", {n!r}'),
            (GUARDS, "-k", "input"),
        )
        for n in RANGED_INPUTS
    ),
    *(
        Mutation(
            f"input {n} range (fast path)", MODEL, FAST_PATH[n], "True", (GUARDS, "-k", "input")
        )
        for n in RANGED_INPUTS
    ),
    Mutation(
        "inputs: any bad value (slow path)",
        MODEL,
        "self._value_problem(table.INPUTS, _INPUT_RANGES)",
        "None",
        (GUARDS, "-k", "input"),
    ),
    # Parameters, checked once per start.
    *(
        Mutation(
            f"parameter {n} finite", VALUES, FINITE_LOOP, _skip(n), (GUARDS, "-k", "parameter")
        )
        for n in PARAMETERS
    ),
    *(
        Mutation(
            f"parameter {n} range",
            MODEL,
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
        VALUES,
        "if self.parameter_fault:\n            return self.parameter_fault.at(self.time)",
        "if False:\n            return self.parameter_fault.at(self.time)",
        (GUARDS, "-k", "parameter or max_bend_angle"),
    ),
    Mutation(
        "bad input_angle_start not used as the start angle",
        MODEL,
        "split_angle(self.input_angle_start if valid else 0.0)",
        "split_angle(self.input_angle_start)",
        (GUARDS, "-k", "parameter"),
    ),
    Mutation(
        "bad yoke_phase not used as the phase",
        MODEL,
        "split_angle(self.yoke_phase if valid else 0.0)",
        "split_angle(self.yoke_phase)",
        (GUARDS, "-k", "parameter"),
    ),
    # The bend angle: now, at the step's end, at the peak inside the step; both paths.
    Mutation(
        "bend angle now (fast path)",
        MODEL,
        "and abs(beta) < guard",
        "and True",
        (GUARDS, "-k", "bend"),
    ),
    Mutation(
        "bend angle at step end (fast path)",
        MODEL,
        "abs(beta + step_size * (rate + 0.5 * acc * step_size)) < guard",
        "True",
        (GUARDS, "-k", "bend"),
    ),
    Mutation(
        "bend peak inside the step (fast path)",
        MODEL,
        "(rate * acc >= 0.0 or -rate / acc >= step_size)",
        "True",
        PEAK_TESTS,
    ),
    Mutation(
        "bend angle now (slow path)",
        MODEL,
        "candidates = [(Reason.BEND_ANGLE, 0.0, beta)]",
        "candidates = [(Reason.BEND_ANGLE, 0.0, 0.0)]",
        (GUARDS, "-k", "bend"),
    ),
    Mutation(
        "bend angle at step end (slow path)",
        MODEL,
        "                    Reason.BEND_AT_STEP_END,\n"
        "                    step_size,\n"
        "                    beta + step_size * (rate + 0.5 * acc * step_size),\n",
        "                    Reason.BEND_AT_STEP_END,\n                    step_size,\n"
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
        "bend angle marks its outputs invalid",
        MODEL,
        "if not abs(self.bend_angle) < self.max_bend_angle:",
        "if False:",
        (GUARDS, "-k", "bend"),
    ),
    # The step itself.
    Mutation(
        "step size finite",
        VALUES,
        "if not (math.isfinite(step_size) and step_size > 0.0):",
        "if not (step_size > 0.0):",
        (GUARDS, "-k", "step_size"),
    ),
    Mutation(
        "step size positive",
        VALUES,
        "if not (math.isfinite(step_size) and step_size > 0.0):",
        "if not (math.isfinite(step_size)):",
        (GUARDS, "-k", "step_size"),
    ),
    Mutation(
        "angle overflow",
        VALUES,
        "if abs(increment) <= MAX_INCREMENT and abs(end_speed) <= speed_limit:",
        "if abs(end_speed) <= speed_limit:",
        (GUARDS, "-k", "beyond_float_precision"),
    ),
    Mutation(
        "angle overflow named as such",
        VALUES,
        "if not abs(increment) <= MAX_INCREMENT:",
        "if False:",
        (GUARDS, "-k", "beyond_float_precision"),
    ),
    Mutation(
        "speed at the step's end",
        VALUES,
        "if abs(increment) <= MAX_INCREMENT and abs(end_speed) <= speed_limit:",
        "if abs(increment) <= MAX_INCREMENT:",
        (GUARDS, "-k", "speed_range"),
    ),
    Mutation(
        "restore: all or nothing",
        VALUES,
        RESTORED,
        RESTORED
        + "        for name, value in values.items():\n            setattr(self, name, value)\n",
        (GUARDS, SLAVE_GUARDS, "-k", "state"),
    ),
    # The rotor models' own guard (the motor's, the inertia load's; their value
    # checks are the ones above).
    Mutation(
        "motor, inertia load: rotor speed at the step's end",
        "fmu_src/cardan_joint/physics/stepped.py",
        "        if not abs(speed) <= limit:\n",
        "        if False:\n",
        (
            "tests/test_driveline.py",
            "tests/test_inertia_load.py",
            "tests/test_refusal.py",
            "-k",
            "unusable_inputs or reads_back or refuses",
        ),
    ),
    # The slave: what the FMU does with a refusal, illegal calls, states.
    Mutation(
        "slave: refused step returns Discard",
        CORE,
        "            if problem:\n                model.time = time\n",
        "            if False:\n                model.time = time\n",
        (SLAVE_GUARDS, "-k", "step"),
    ),
    Mutation(
        "slave: refused step leaves the clock",
        CORE,
        "                model.time = time\n                self._report(",
        "                self._report(",
        (f"{ROBUSTNESS}::test_a_refused_step_leaves_the_clock_alone",),
    ),
    Mutation(
        "slave: invalid inputs hold outputs",
        CORE,
        "            if problem:\n                self._report(\n"
        "                    f\"{problem.at(model.time).message}; outputs that depend on it \"",
        "            if False:\n                self._report(\n"
        "                    f\"{problem.at(model.time).message}; outputs that depend on it \"",
        (SLAVE_GUARDS, "-k", "held"),
    ),
    Mutation(
        "slave: held outputs follow the declared dependencies",
        CORE,
        "live[i] if dependencies & invalid else fresh[i]",
        "fresh[i]",
        (f"{ROBUSTNESS}::test_invalid_load_holds_only_the_outputs_that_depend_on_it",),
    ),
    Mutation(
        "slave: bad parameters are an error at initialization",
        CORE,
        "            problem = self._model.parameter_fault\n            if problem:",
        "            problem = self._model.parameter_fault\n            if False:",
        (SLAVE_GUARDS, "-k", "initialization"),
    ),
    Mutation(
        "slave: set on an output or unknown reference",
        CORE,
        "if not 0 <= i < refs.first_output:",
        "if False:",
        (SLAVE_GUARDS, "-k", "setting"),
    ),
    Mutation(
        "slave: parameter set after initialization",
        CORE,
        "elif self._initialized:",
        "elif False:",
        (SLAVE_GUARDS, "-k", "after_initialization"),
    ),
    Mutation(
        "slave: get of an unknown reference",
        SLAVE,
        "            if bad:\n",
        "            if False:\n",
        (SLAVE_GUARDS, "-k", "unknown_reference"),
    ),
    *(
        Mutation(
            f"slave: {call} on the Real-only FMU",
            SLAVE,
            f"def {call}(self, vrs",
            f"def _unused_{call}(self, vrs",
            (SLAVE_GUARDS, "-k", "other_variable_types"),
        )
        for call in (
            "get_integer",
            "get_boolean",
            "get_string",
            "set_integer",
            "set_boolean",
            "set_string",
        )
    ),
    Mutation(
        "slave: a marked invalid state",
        CORE,
        'if "invalid_state" in state:',
        "if False:",
        (SLAVE_GUARDS, "-k", "state"),
    ),
    Mutation(
        "slave: a state of another version",
        CORE,
        "if (\n"
        '                "model" not in state\n'
        "                or len(held_outputs) != len(self.table.OUTPUTS)\n"
        "                or len(held_inputs) != len(self.table.INPUTS)\n"
        "            ):",
        "if False:",
        (SLAVE_GUARDS, "-k", "state"),
    ),
    Mutation(
        "slave: deserialized bytes that are no dict",
        CORE,
        "if not isinstance(state, dict):",
        "if False:",
        (SLAVE_GUARDS, "-k", "state"),
    ),
    Mutation(
        "slave: deserialized bytes that are no JSON",
        CORE,
        'return {"invalid_state": reason}',
        "raise",
        (SLAVE_GUARDS, "-k", "state"),
    ),
    # The one-call step (issue 21): what the native loader may keep of its buffers.
    Mutation(
        "one-call step: a refused step writes no outputs",
        FAST_STEP,
        "        if status:  # refused or faulted",
        "        if False:  # refused or faulted",
        (FAST_STEP_TESTS, "-k", "refused_step or normal_paths"),
    ),
    Mutation(
        "one-call step: the inputs a step moved are written back",
        FAST_STEP,
        "            refs.pack_inputs(known, 0, *self._inputs_held)\n",
        "            pass\n",
        (FAST_STEP_TESTS, "-k", "normal_paths"),
    ),
    Mutation(
        "one-call step: held outputs are not kept",
        FAST_STEP,
        "return self._STATUS.ok if self._outputs is not None else self._STATUS.warning",
        "return self._STATUS.ok",
        (FAST_STEP_TESTS, "-k", "refused_step or normal_paths"),
    ),
    Mutation(
        "one-call step: a read after an input write checks the inputs",
        FAST_STEP,
        "        self._outputs = None\n        self._inputs_checked = False\n",
        "        self._outputs = None\n",
        (FAST_STEP_TESTS, "-k", "normal_paths"),
    ),
    # The build, called as a library: the caller's sys.modules as it was.
    Mutation(
        "build: drops its staged modules",
        "fmu_src/cardan_joint/build/builder.py",
        "n.split(\".\")[0] in (package_dir.name,",
        "n.split(\".\")[0] in (package_dir.name + \"_\",",
        ("tests/test_build.py",),
    ),
    # Plumbing that keeps a user's result and messages clean.
    Mutation(
        "simulate: a refused run ends at its last good point",
        "fmu_src/cardan_joint/host/simulate.py",
        "            result = _without_repeated_end(result)\n",
        "            pass\n",
        ("tests/test_refusal.py", "-k", "simulate_raises"),
    ),
    Mutation(
        "sweep: Dask missing names its extra",
        "fmu_src/cardan_joint/sweep/command.py",
        "    if not args.serial:\n        try:\n            require(",
        "    if False:\n        try:\n            require(",
        ("tests/test_extras.py", "-k", "sweep"),
    ),
    Mutation(
        "cosim: libcosimpy missing names its extra",
        "fmu_src/cardan_joint/host/cosim.py",
        '    require("libcosimpy", "cosim", "running in libcosim")\n'
        "    from libcosimpy.CosimExecution import CosimExecution\n"
        "    from libcosimpy.CosimLogging import CosimLogLevel, log_output_level\n\n",
        "    from libcosimpy.CosimExecution import CosimExecution\n"
        "    from libcosimpy.CosimLogging import CosimLogLevel, log_output_level\n\n",
        ("tests/test_extras.py", "-k", "libcosim_runs"),
    ),
    # The compliant driveline (issue 20).
    Mutation(
        "compliant: no kinematics at a start with unusable inputs",
        COMPLIANT,
        "        valid = not self.parameter_fault and not self.rigid.input_problem()\n",
        "        valid = not self.parameter_fault\n",
        (COMPLIANT_TESTS, "-k", "unusable_bend"),
    ),
    Mutation(
        "compliant: the spring's torque leaves the rigid load check",
        COMPLIANT,
        "        try:\n            values = rigid.outputs()\n        finally:\n"
        "            rigid.load_torque = 0.0\n",
        "        values = rigid.outputs()\n",
        (COMPLIANT_TESTS, "-k", "rigid_load_range"),
    ),
    Mutation(
        "compliant: twist overflow refused",
        COMPLIANT,
        "        if not abs(change) <= MAX_INCREMENT:\n",
        "        if False:\n",
        (COMPLIANT_TESTS, "-k", "twist_beyond"),
    ),
    Mutation(
        "exact rotor step: series near zero drag",
        "fmu_src/cardan_joint/physics/stepped.py",
        "    if abs(z) > 0.05:\n",
        "    if True:\n",
        ("tests/test_inertia_load.py",),
    ),
    Mutation(
        "ssp: a missing file is named",
        "fmu_src/cardan_joint/host/ssp.py",
        "    if not path.is_file():\n",
        "    if False:\n",
        ("tests/test_compliant_system.py", "-k", "broken"),
    ),
)
