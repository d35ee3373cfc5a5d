"""The mutation table's plumbing guards (tools/guards.py): the build as a
library, the host's result and messages, the optional extras, the compliant
driveline and the SSP reader."""

from guards_base import (
    COMPLIANT,
    COMPLIANT_TESTS,
    Mutation,
)

PLUMBING_MUTATIONS = (
    # The build, called as a library: the caller's sys.modules as it was.
    Mutation(
        "build: drops its staged modules",
        "fmu_src/cardan_joint/build/builder.py",
        "n.split(\".\")[0] in (package_dir.name,",
        "n.split(\".\")[0] in (package_dir.name + \"_\",",
        ("tests/fmu/test_build.py",),
    ),
    # Plumbing that keeps a user's result and messages clean.
    Mutation(
        "simulate: a refused run ends at its last good point",
        "fmu_src/cardan_joint/host/simulate.py",
        "            result = _without_repeated_end(result)\n",
        "            pass\n",
        ("tests/fmu/test_refusal.py", "-k", "simulate_raises"),
    ),
    Mutation(
        "instance: a stop signal during any call into the FMU is raised after it",
        "fmu_src/cardan_joint/host/instance.py",
        "        held.holding = True\n        try:\n            yield\n",
        "        held.holding = False\n        try:\n            yield\n",
        ("tests/fmu/test_no_debris.py", "-k", "any_call"),
    ),
    Mutation(
        "sweep: Dask missing names its extra",
        "fmu_src/cardan_joint/sweep/command.py",
        "    if not args.serial:\n        try:\n            require(",
        "    if False:\n        try:\n            require(",
        ("tests/fmu/test_extras.py", "-k", "sweep"),
    ),
    Mutation(
        "cosim: libcosimpy missing names its extra",
        "fmu_src/cardan_joint/host/cosim.py",
        '    require("libcosimpy", "cosim", "running in libcosim")\n'
        "    from libcosimpy.CosimExecution import CosimExecution\n"
        "    from libcosimpy.CosimLogging import CosimLogLevel, log_output_level\n\n"
        "    step_ns, n_steps = _steps(",
        "    from libcosimpy.CosimExecution import CosimExecution\n"
        "    from libcosimpy.CosimLogging import CosimLogLevel, log_output_level\n\n"
        "    step_ns, n_steps = _steps(",
        ("tests/fmu/test_extras.py", "-k", "libcosim_runs"),
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
        "fmu_src/cardan_joint/physics/rotor.py",
        "    if abs(z) > 0.05:\n",
        "    if True:\n",
        ("tests/fmu/test_inertia_load.py",),
    ),
    Mutation(
        "ssp: a missing file is named",
        "fmu_src/cardan_joint/host/ssp.py",
        "    if not path.is_file():\n",
        "    if False:\n",
        ("tests/fmu/test_compliant_system.py", "-k", "broken"),
    ),
    # A host's environment: the loader honours the user's Python.
    Mutation(
        "loader: the user's Python before the build's and the machine's",
        "fmu_src/cardan_joint/fmi/native/python_discovery.c",
        "    if (record->user.library[0]) {\n        *found = record->user;\n",
        "    if (0) {\n        *found = record->user;\n",
        ("tests/fmu/test_c_host.py", "-k", "users_python"),
    ),
    Mutation(
        "runtime: a getter's values are copied only when they are as many as asked for",
        "fmu_src/cardan_joint/fmi/native/slave_values.c",
        "    if (size != (Py_ssize_t)n_values) {\n",
        "    if (0) {\n",
        ("tests/fmu/test_damaged_resources.py", "-k", "getter"),
    ),
    Mutation(
        "runtime: a string that is not UTF-8 is refused by name, never a NULL item",
        "fmu_src/cardan_joint/fmi/native/slave_values.c",
        "        if (!one) {",
        "        if (0) {",
        ("tests/fmu/test_honest_statuses.py", "-k", "utf8"),
    ),
    Mutation(
        "runtime: bytes the slave refuses make no FMU state",
        "fmu_src/cardan_joint/fmi/native/slave_values.c",
        "    if (result == py_none) {",
        "    if (0) {",
        ("tests/fmu/test_honest_statuses.py", "-k", "deserialize"),
    ),
    Mutation(
        "runtime: a state passed where its address belongs is named, never read",
        "fmu_src/cardan_joint/fmi/native/state_book.c",
        "    if (find_state(in, (fmi2FMUstate)state) != (size_t)-1) {",
        "    if (0) {",
        ("tests/fmu/test_honest_statuses.py", "-k", "address"),
    ),
    Mutation(
        "runtime: a call after the host finalized Python is an error, not a signal",
        "fmu_src/cardan_joint/fmi/native/calls.c",
        "    if (enter_python_thread()) {",
        "    if (0) {",
        ("tests/fmu/test_host_python.py", "-k", "finalized_python"),
    ),
    Mutation(
        "runtime: an instantiate after the host finalized Python is NULL, not a signal",
        "fmu_src/cardan_joint/fmi/native/python_runtime.c",
        "    if (python_ready && !p_Py_IsInitialized()) {",
        "    if (0) {",
        ("tests/fmu/test_host_python.py", "-k", "finalized_python"),
    ),
    Mutation(
        "runtime: a libpython the host holds is the one started or joined, never a second",
        "fmu_src/cardan_joint/fmi/native/python_runtime.c",
        "    int n = loaded_pythons(loaded, sizeof loaded, names, sizeof names);",
        "    int n = 0 * loaded_pythons(loaded, sizeof loaded, names, sizeof names);",
        ("tests/fmu/test_host_python.py", "-k", "own_python"),
    ),
    Mutation(
        "runtime: several libpythons in the host are refused by name",
        "fmu_src/cardan_joint/fmi/native/python_runtime.c",
        "    if (n > 1) {",
        "    if (0) {",
        ("tests/fmu/test_host_python.py", "-k", "two_libpythons"),
    ),
    Mutation(
        "runtime: a host thread's Python state ends while CPython's slot still names it",
        "fmu_src/cardan_joint/fmi/native/python_runtime.c",
        "    if (main_thread || !at_thread_exit ||",
        "    if (1 ||",
        ("tests/system/test_debug_python.py",),
    ),
    Mutation(
        "runtime: a process-wide start object of another layout is refused, never used",
        "fmu_src/cardan_joint/fmi/native/process_object.c",
        "        found == mine)",
        "        1)",
        ("tests/fmu/test_process_layout.py",),
    ),
    Mutation(
        "runtime: FMI 3.0 accessors of types the slave has not refuse every reference",
        "fmu_src/cardan_joint/fmi/native/fmi3_calls.c",
        "        if (nvr == 0)" + " " * 72 + "\\\n",  # in a macro
        "        if (1)" + " " * 79 + "\\\n",
        ("tests/fmu/test_damaged_resources.py", "-k", "another_type"),
    ),
)
