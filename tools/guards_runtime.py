"""The mutation table's guards of the native runtime's own checks (tools/guards.py,
docs/runtime.md): counts it is given, the error state, the interrupt handed back,
and a refused FMU state that changes nothing."""

from guards_base import Mutation

NATIVE = "fmu_src/cardan_joint/fmi/native/"
GENERATED_TESTS = "tests/fmu/test_generated_step.py"

RUNTIME_MUTATIONS = (
    Mutation(
        "runtime: a slave that cannot catch up leaves the instance in the error state",
        NATIVE + "fast_path.c",
        "    fast->generated = 0;\n    in->state = STATE_ERROR;",
        "    fast->generated = 0;\n    return 0;",
        (GENERATED_TESTS, "-k", "error_state"),
    ),
    Mutation(
        "runtime: the slave's layout counts are checked",
        NATIVE + "fast_path.c",
        "        found = sizes_taken(in, fast) &&",
        "        found = 1 &&",
        (GENERATED_TESTS, "-k", "beyond"),
    ),
    Mutation(
        "runtime: FMI 3's reference starts are checked",
        NATIVE + "fast_references.c",
        "    for (long long vr = 1; ok && vr <= refs; vr++)\n"
        "        ok = fast->table[vr] <= fast->table[vr + 1];",
        "",
        ("tests/unit/test_runtime_units.py", "-k", "table"),
    ),
    Mutation(
        "runtime: a value reference beyond the slave's is not served from the arrays",
        NATIVE + "fast_references.c",
        "if (vr[i] >= references || !(fast->serves[vr[i]] & needed))",
        "if (!(fast->serves[vr[i] % references] & needed))",
        ("tests/fmu/test_fast_path.py", "-k", "plain_calls"),
    ),
    Mutation(
        "runtime: only inputs are written into the arrays",
        NATIVE + "fast_references.c",
        "!(fast->serves[vr[i]] & needed)",
        "!fast->serves[vr[i]]",
        ("tests/fmu/test_fast_path.py", "-k", "plain_calls"),
    ),
    Mutation(
        "runtime: a KeyboardInterrupt in the slave is handed back to the host",
        NATIVE + "slave_object.c",
        "    p_PyErr_SetInterrupt();",
        "",
        ("tests/fmu/test_host_interrupts.py", "-k", "handed_back"),
    ),
    Mutation(
        "runtime: a change of mode interrupted in the slave keeps the error state",
        NATIVE + "calls.c",
        "    if (status <= fmi2Error && in->state == was)",
        "    if (status <= fmi2Error && in->state != STATE_FATAL)",
        ("tests/fmu/test_host_interrupts.py", "-k", "initialization"),
    ),
    Mutation(
        "runtime: a refused FMU state leaves the arrays as they were",
        NATIVE + "state_book.c",
        "    if (!refused)",
        "    if (1)",
        ("tests/fmu/test_fast_path.py", "-k", "refused_fmu_state"),
    ),
    Mutation(
        "slave: a refused FMU state keeps the outputs' cache",
        "fmu_src/cardan_joint/fmi/fmu_state.py",
        "            return True\n        self._outputs = None",
        "            self._outputs = None\n            return True\n        self._outputs = None",
        ("tests/fmu/test_slave_guards.py", "-k", "state"),
    ),
    Mutation(
        "slave: a step in C hands over at an output's smallest armed limit",
        "fmu_src/cardan_joint/fmi/watching.py",
        "limits[slot] = min(limits[slot], limit)",
        "limits[slot] = limit",
        ("tests/unit/test_watch_rows.py", "-k", "smallest"),
    ),
)
