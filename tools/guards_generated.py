"""The mutation table's guards of the generated step (tools/guards.py,
docs/codegen.md): the generator's operation-for-operation translation, the
build's check of the runtime's convention, and the runtime keeping the slave in
step with the steps it takes in C: its watches and the reads it passes on
(the life integral the default build's step runs: tools/guards_life.py)."""

from guards_base import ROTOR_MODEL, Mutation

EXPRESSIONS = "fmu_src/cardan_joint/codegen/expressions.py"
STEP_SOURCE = "fmu_src/cardan_joint/build/step_source.py"
FAST_PATH = "fmu_src/cardan_joint/fmi/native/fast_path.c"
FAST_VALUES = "fmu_src/cardan_joint/fmi/native/fast_values.c"
GENERATED = "fmu_src/cardan_joint/fmi/native/generated.c"
BIT_TEST = ("tests/unit/test_codegen_joint.py", "-k", "python_steps_bits")
BUILD_TESTS = "tests/unit/test_codegen_build.py"
FUNCTIONS = "fmu_src/cardan_joint/codegen/functions.py"
UNROLLED = "fmu_src/cardan_joint/codegen/unrolled.py"
REFUSALS = ("tests/unit/test_codegen.py", "-k", "untranslatable")
RUNTIME_TESTS = "tests/fmu/test_generated_step.py"
WRITTEN_STEP = "fmu_src/cardan_joint/framework/written_step.py"
LOAD_STEP = "fmu_src/cardan_joint/models/load/step.py"
# A written step takes only what the checks take (the C and the Python step
# run the same source, so only this comparison sees its own guards).
CHECKS_TAKE = ("tests/unit/test_codegen_models.py", "-k", "checks_take")
COMPLIANT_STEP = "fmu_src/cardan_joint/models/compliant_joint/step.py"
COMPLIANT_TESTS = "tests/unit/test_codegen_compliant.py"
ENTRY = "fmu_src/cardan_joint/framework/grouped_entry.py"
UNIT = "fmu_src/cardan_joint/codegen/unit.py"
ENTRY_TESTS = ("tests/unit/test_codegen_entry.py",)

GENERATED_MUTATIONS = (
    Mutation(
        "generated step: Python's grouping kept",
        EXPRESSIONS,
        'return f"({text})"',
        "return text",
        BIT_TEST,
    ),
    Mutation(
        "generated step: a true division of two counts",
        EXPRESSIONS,
        'left = f"(double){left}"',
        "pass",
        ("tests/unit/test_codegen.py", "-k", "gives_pythons_bits"),
    ),
    Mutation(
        "generated step: the runtime's argument order checked",
        STEP_SOURCE,
        'names[:2] != ("time", "h") or given != known[: len(given)]',
        'names[:2] != ("time", "h")',
        (BUILD_TESTS, "-k", "convention"),
    ),
    Mutation(
        "generated step: its sizes are the slave's",
        GENERATED,
        "generated_step_sizes[1] != fast->state_size + fast->inputs + fast->outputs",
        "0",
        (BUILD_TESTS, "-k", "sizes"),
    ),
    Mutation(
        "generated step: a step in C leaves the slave behind",
        FAST_VALUES,
        "fast->behind = 1;",
        "fast->behind = 0;",
        (RUNTIME_TESTS,),
    ),
    Mutation(
        "generated step: the slave catches up before any other call",
        FAST_VALUES,
        "    if (catch_up(in))\n        return -1;\n",
        "",
        (RUNTIME_TESTS,),
    ),
    Mutation(
        "generated step: the slave catches up before it steps or evaluates",
        FAST_PATH,
        "    if (method != FAST_SYNC && catch_up(in))\n        return fmi2Error;",
        "",
        (RUNTIME_TESTS,),
    ),
    Mutation(
        "generated step: a watch passed by a step in C is warned of",
        FAST_VALUES,
        "return watch_passed(fast) ? (fmi2Status)fast_call(in, FAST_WATCH) : fmi2OK;",
        "return fmi2OK;",
        (RUNTIME_TESTS, "-k", "past_the_rated_torque"),
    ),
    Mutation(
        "fast path: a step the slave takes is stored (its outputs, the moved inputs)",
        FAST_VALUES,
        "return take_reply(fast, FAST_STORE, p_PyTuple_GetItem(reply, 1));",
        "return fmi2OK;",
        ("tests/fmu/test_fast_path.py", "-k", "plain_calls"),
    ),
    Mutation(
        "fast path: a step reply's length is checked",
        FAST_VALUES,
        "        if (size != 2) {",
        "        if (size < 0) {",
        ("tests/fmu/test_fast_path_replies.py", "-k", "malformed_step_reply"),
    ),
    Mutation(
        "fast path: a read passes the indices it reads",
        FAST_VALUES,
        "fast->reading = vr, fast->reading_count = n;",
        "fast->reading = vr, fast->reading_count = 0;",
        ("tests/fmu/test_fast_path.py", "-k", "plain_calls"),
    ),
    Mutation(
        "compliant step: the output shaft's speed in its range",
        COMPLIANT_STEP,
        "abs(output_speed) <= OUTPUT_SPEED_LIMIT",
        "abs(output_speed) <= 1e300",
        (COMPLIANT_TESTS, "-k", "past_its_limit"),
    ),
    Mutation(
        "compliant step: the output shaft's acceleration in its range",
        COMPLIANT_STEP,
        "abs(output_acceleration) <= OUTPUT_ACCELERATION_LIMIT",
        "abs(output_acceleration) <= 1e300",
        (COMPLIANT_TESTS, "-k", "past_its_limit"),
    ),
    Mutation(
        "compliant step: the twist's change per step bounded",
        COMPLIANT_STEP,
        "and abs(change) <= MAX_INCREMENT",
        "and abs(change) <= 1e300",
        (COMPLIANT_TESTS, "-k", "twist_limit"),
    ),
    Mutation(
        "generated step: a tuple takes a new shape in straight-line code only",
        FUNCTIONS,
        "isinstance(kind, Tuple) and not self.branching)",
        "isinstance(kind, Tuple))",
        REFUSALS,
    ),
    Mutation(
        "generated step: no break out of an unrolled loop",
        UNROLLED,
        "if self.loops and self.loops[-1]:",
        "if False:",
        REFUSALS,
    ),
    Mutation(
        "written step: the step size checked",
        WRITTEN_STEP,
        "return 0.0 < h < math.inf and parameters_valid",
        "return parameters_valid",
        CHECKS_TAKE,
    ),
    Mutation(
        "written step: the parameters checked",
        WRITTEN_STEP,
        "return 0.0 < h < math.inf and parameters_valid",
        "return 0.0 < h < math.inf",
        CHECKS_TAKE,
    ),
    Mutation(
        "rotor step (Motor, InertiaLoad): the torque's range",
        ROTOR_MODEL,
        "torque_low <= torque <= torque_high",
        "True",
        CHECKS_TAKE,
    ),
    Mutation(
        "rotor step (Motor, InertiaLoad): the rotor speed at the step's end",
        ROTOR_MODEL,
        "    if not within:\n        return None\n",
        "",
        CHECKS_TAKE,
    ),
    Mutation(
        "load's step: the speed's range",
        LOAD_STEP,
        "SPEED_LOW <= speed <= SPEED_HIGH",
        "True",
        CHECKS_TAKE,
    ),
    Mutation(
        "load's step: the acceleration's range",
        LOAD_STEP,
        "ACCELERATION_LOW <= acceleration <= ACCELERATION_HIGH",
        "True",
        CHECKS_TAKE,
    ),
    Mutation(
        "grouped entry: a parameter takes the argument it names",
        ENTRY,
        "            if count == 0:",
        "            if False:",
        ENTRY_TESTS,
    ),
    Mutation(
        "grouped entry: every group names a parameter",
        ENTRY,
        "        if groups:",
        "        if False:",
        ENTRY_TESTS,
    ),
    Mutation(
        "grouped entry: Python takes exactly its flat arguments",
        ENTRY,
        "        if len(values) != len(self.arguments):",
        "        if False:",
        ENTRY_TESTS,
    ),
    Mutation(
        "grouped entry: a group's tuple has its size in C",
        UNIT,
        "if (size is None) != isinstance(kind, Scalar) or len(items) != (size or 1):",
        "if False:",
        ENTRY_TESTS,
    ),
)
