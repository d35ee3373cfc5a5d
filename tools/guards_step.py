"""The mutation table's step and slave guards (tools/guards.py): the step
itself, the rotor models' own guard, the slave's answers to refusals, illegal
calls and states, and the slave's side of the fast path."""

from guards_base import (
    CORE,
    FAST_PATH,
    FMU_STATE,
    GUARDS,
    HONEST,
    REFERENCES,
    RESTORED,
    ROBUSTNESS_CALLS,
    ROTOR_MODEL,
    SLAVE,
    SLAVE_ARRAYS,
    SLAVE_GUARDS,
    STEPPED,
    VALUES,
    WATCH_TESTS,
    WATCH_UNIT_TESTS,
    WATCHES,
    WATCHING,
    WRITTEN_STEP,
    Mutation,
)

STEP_MUTATIONS = (
    # The step itself.
    Mutation(
        "step size finite",
        STEPPED,
        "if not (math.isfinite(step_size) and step_size > 0.0):",
        "if not (step_size > 0.0):",
        (GUARDS, "-k", "step_size"),
    ),
    Mutation(
        "step size positive",
        STEPPED,
        "if not (math.isfinite(step_size) and step_size > 0.0):",
        "if not (math.isfinite(step_size)):",
        (GUARDS, "-k", "step_size"),
    ),
    Mutation(
        "angle overflow",
        STEPPED,
        "if abs(increment) <= MAX_INCREMENT and abs(end_speed) <= self._speed_limit:",
        "if abs(end_speed) <= self._speed_limit:",
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
        STEPPED,
        "if abs(increment) <= MAX_INCREMENT and abs(end_speed) <= self._speed_limit:",
        "if abs(increment) <= MAX_INCREMENT:",
        (GUARDS, "-k", "speed_range"),
    ),
    Mutation(
        "a written step's model: a step it does not take goes through the checks",
        WRITTEN_STEP,
        "            return super().run(time, step_size, inputs)\n",
        "            pass\n",
        (SLAVE_ARRAYS, "-k", "normal_paths"),
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
        ROTOR_MODEL,
        "abs(end_speed) <= speed_limit",
        "True",
        (
            "tests/fmu/test_driveline.py",
            "tests/fmu/test_inertia_load.py",
            "tests/fmu/test_refusal.py",
            "-k",
            "unusable_inputs or reads_back or refuses",
        ),
    ),
    # The slave: what the FMU does with a refusal, illegal calls, states.
    Mutation(
        "slave: refused step returns Error",
        CORE,
        "            if isinstance(result, Refusal):\n",
        "            if False:\n",
        (SLAVE_GUARDS, "-k", "step"),
    ),
    Mutation(
        "slave: refused step leaves the clock",
        STEPPED,
        "            self.time = before\n            return problem\n",
        "            return problem\n",
        (f"{ROBUSTNESS_CALLS}::test_a_refused_step_leaves_the_clock_alone",),
    ),
    Mutation(
        "slave: invalid inputs hold outputs",
        CORE,
        "            if problem:\n                outputs, held = self._held_outputs(model)",
        "            if False:\n                outputs, held = self._held_outputs(model)",
        (SLAVE_GUARDS, "-k", "held"),
    ),
    Mutation(
        "slave: held outputs follow the declared dependencies",
        CORE,
        "live[i] if i in held else value",
        "value",
        (f"{ROBUSTNESS_CALLS}::test_invalid_load_holds_only_the_outputs_that_depend_on_it",),
    ),
    Mutation(
        "slave: only a read of a held output warns",
        CORE,
        "if read is None or any(i - self._refs.first_output in held for i in read):",
        "if True:",
        (f"{SLAVE_ARRAYS}::test_only_an_output_that_depends_on_an_invalid_input_warns",),
    ),
    Mutation(
        "slave: bad parameters are an error at initialization",
        CORE,
        "            problem = self._model.parameter_fault\n            if problem:",
        "            problem = self._model.parameter_fault\n            if False:",
        (SLAVE_GUARDS, "-k", "initialization"),
    ),
    Mutation(
        "slave: set on an output",
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
        "slave: get or set of an unknown reference",
        REFERENCES,
        "if not FIRST_VALUE_REFERENCE <= vr < len(table):",
        "if False:",
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
        FMU_STATE,
        'if "invalid_state" in state:',
        "if False:",
        (SLAVE_GUARDS, "-k", "state"),
    ),
    Mutation(
        "slave: a state of another version",
        FMU_STATE,
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
        FMU_STATE,
        "if not isinstance(state, dict):",
        "if False:",
        (SLAVE_GUARDS, "-k", "state"),
    ),
    Mutation(
        "slave: deserialized bytes are checked as a set state would be",
        FMU_STATE,
        "            self._new_model().restore(self._checked_state(state)[0])\n",
        "",
        (HONEST, "-k", "deserialize"),
    ),
    Mutation(
        "slave: a state is checked whole before any of it is applied",
        FMU_STATE,
        "            model_state, start_time, initialized, outputs, inputs, passed = "
        "self._checked_state(state)\n"
        "            self._model.restore(model_state)",
        '            self._model.restore(state["model"])\n'
        "            model_state, start_time, initialized, outputs, inputs, passed = "
        "self._checked_state(state)",
        (SLAVE_GUARDS, "-k", "start_time"),
    ),
    # The slave's side of the fast path: what the runtime may keep of its arrays.
    Mutation(
        "fast path: a taken step's outputs are stored",
        FAST_PATH,
        "(self._refs.known_of(self._model), self._outputs_held)",
        "(self._refs.known_of(self._model), self._refs.nan_outputs)",
        (SLAVE_ARRAYS, "-k", "normal_paths"),
    ),
    Mutation(
        "fast path: held outputs are not kept",
        FAST_PATH,
        "return (self._STATUS.warning if held else self._STATUS.ok), outputs",
        "return self._STATUS.ok, outputs",
        (SLAVE_ARRAYS, "-k", "refused_step or normal_paths"),
    ),
    Mutation(
        "fast path: a read after an input write checks the inputs",
        FAST_PATH,
        "set_inputs(inputs)\n        self._outputs = None\n        self._inputs_checked = False\n",
        "set_inputs(inputs)\n        self._outputs = None\n",
        (SLAVE_ARRAYS, "-k", "normal_paths"),
    ),
    # The watches (framework/watches.py): each output past its limit once, the run on.
    Mutation(
        "watches: a step in Python checks them",
        CORE,
        "            if self._armed:\n                self._watch(outputs)\n",
        "",
        ("tests/fmu/test_generated_step.py", "-k", "rated_torque"),
    ),
    Mutation(
        "watches: a passed watch is disarmed",
        WATCHES,
        "        else:\n            kept.append((watch, limit))\n",
        "        kept.append((watch, limit))\n",
        (WATCH_UNIT_TESTS, WATCH_TESTS, "-k", "once"),
    ),
    Mutation(
        "watches: an output is compared by its magnitude",
        WATCHES,
        "if abs(outputs[slot]) > limit:",
        "if outputs[slot] > limit:",
        (WATCH_UNIT_TESTS, "-k", "magnitude"),
    ),
    Mutation(
        "watches: a state's passed watches are read before the model is restored",
        FMU_STATE,
        'tuple(map(str, state.get("watches_passed", ())))',
        'state.get("watches_passed", ())',
        (WATCH_TESTS, "-k", "malformed"),
    ),
    Mutation(
        "watches: a state brings back the watches passed then",
        WATCHING,
        "arm(self._watched, self._model, passed_already)",
        "arm(self._watched, self._model)",
        (WATCH_TESTS, "-k", "state"),
    ),
)
