"""What the FMI 2 and FMI 3 slaves share: the joint behind the variables.

Both pythonfmu libraries turn any Python exception into a fatal status, so
every method here that a slave calls catches everything. This mixin keeps the
FMI-version-independent part: the joint, the output cache, the held outputs
while an input is invalid, the refused step that leaves the joint untouched,
the parameters fixed after initialization, and the complete FMU state. It
addresses variables by *flat index*: the position in `variables.VARIABLES`
(inputs, parameters, outputs), which is the FMI 2 value reference; the FMI 3
slave maps its value references (arrays included) onto the same indices.

A slave class mixes it in before its pythonfmu base and provides `_STATUS`
(its status enumeration), `_API` ("fmi2" or "fmi3", for messages naming FMI
functions) and `_report(message, status)`.
"""

import json
import math
import sys
from operator import attrgetter

from .. import __version__
from .. import variables as table
from ..physics.model import CardanJoint

KNOWN = table.INPUTS + table.PARAMETERS
NAMES = KNOWN + table.OUTPUTS
FIRST_OUTPUT = len(KNOWN)
assert tuple(v.name for v in table.VARIABLES) == NAMES, \
    "flat indices assume inputs, then parameters, then outputs"
assert table.OUTPUTS[0] == "input_angle", "held outputs keep the first one, the state, live"
INPUT_INDICES = range(len(table.INPUTS))
_NAN_OUTPUTS = (math.nan,) * len(table.OUTPUTS)
_OUTPUT_DEPENDENCIES = tuple(frozenset(table.BY_NAME[n].depends_on) for n in table.OUTPUTS)
_inputs_of = attrgetter(*table.INPUTS)
# What FMPy and most masters pass every step: all inputs, all outputs, in order.
ALL_INPUTS = list(INPUT_INDICES)
ALL_OUTPUTS = list(range(FIRST_OUTPUT, len(NAMES)))

AUTHOR = "Cardan joint FMU team"
LICENSE = "MIT"
VERSION = __version__
DESCRIPTION = ("Exact Cardan (Hooke) universal joint: output shaft motion, crosspiece "
               "orientation and dynamics, input torque and secondary couples")
START_TIME, STOP_TIME, STEP_SIZE = 0.0, 2.0, 1e-3


def log_categories(api: str) -> dict:
    return {
        "logStatusWarning": "Warnings: outputs held at the last valid inputs.",
        "logStatusDiscard": "Refused steps: the variable, its value, the limit and the time.",
        "logStatusError": "Errors: invalid parameters, calls FMI does not allow, internal faults.",
        "logStatusFatal": f"Not used: the FMU never ends in {api}Fatal on its own.",
        "logAll": "All messages.",
    }


class JointCore:
    # Start values that differ from the table's, written in by the build script.
    start_overrides: dict = {}

    def _init_joint(self):
        self._joint = CardanJoint(**self.start_overrides)
        self._start_time = 0.0
        self._initialized = False
        self._outputs = None            # cached outputs; None = recompute on next read
        self._inputs_checked = False
        self._last_message = None
        self._outputs_held, self._inputs_held = _NAN_OUTPUTS, _inputs_of(self._joint)
        if not (self._joint.parameter_fault or self._joint.input_problem()):
            self._outputs_held = self._joint.outputs()

    def _echo_to_stderr(self, message: str, status) -> None:
        """Also write a message to stderr, once per distinct message, for hosts whose
        logger never sees it; a host without a usable stderr must not make it fatal."""
        if message != self._last_message:
            self._last_message = message
            try:
                sys.stderr.write(f"[{self.modelName} {self.instance_name}] "
                                 f"{status.name.upper()}: {message}\n")
                sys.stderr.flush()
            except Exception:
                pass

    def _fault(self, where: str, error: BaseException) -> None:
        try:
            self._report(f"internal error in {where}: {type(error).__name__}: {error}",
                         self._STATUS.error)
        except Exception:
            pass

    # --- life cycle ----------------------------------------------------------

    def _restart(self):
        """Re-apply the start time and parameters (before initialization ends)."""
        self._joint.start(self._start_time)
        self._outputs = None
        self._inputs_checked = False

    def exit_initialization_mode(self):
        try:
            self._restart()
            self._initialized = True
            problem = self._joint.parameter_fault
            if problem:
                self._report(f"{problem}; every step will be refused until it is fixed",
                             self._STATUS.error)
        except Exception as error:
            self._fault("exit_initialization_mode", error)

    def _step(self, current_time, step_size):
        """Take the step; return the status: ok, discard (refused, the joint as it
        was), or error (an internal fault, reported)."""
        try:
            joint = self._joint
            time = joint.time
            joint.time = current_time
            problem = joint.step(step_size)
            if problem:
                joint.time = time
                self._report(f"t = {current_time!r} s: {problem}; step of {step_size!r} s "
                             f"refused, the joint stays at t = {current_time!r} s",
                             self._STATUS.discard)
                return self._STATUS.discard
            self._outputs = None
            self._inputs_checked = True
            return self._STATUS.ok
        except Exception as error:
            self._fault("do_step", error)
            return self._STATUS.error

    # --- values --------------------------------------------------------------

    def _current_outputs(self):
        joint = self._joint
        if not self._inputs_checked:
            problem = joint.parameter_fault or joint.input_problem()
            if problem:
                self._report(f"t = {joint.time!r} s: {problem}; outputs that depend on it "
                             f"are held at the last valid inputs", self._STATUS.warning)
                return self._held_outputs(joint)
            self._inputs_checked = True
        self._outputs = self._outputs_held = joint.outputs()
        self._inputs_held = _inputs_of(joint)
        return self._outputs

    def _held_outputs(self, joint):
        """Outputs with invalid inputs: each output that depends on an invalid input
        keeps its last valid value, the others (and the input angle, the state)
        follow the valid inputs, as the declared dependencies promise."""
        live = (joint.input_angle,) + self._outputs_held[1:]
        if joint.parameter_fault:
            return live
        invalid = joint.invalid_inputs()
        current = _inputs_of(joint)
        try:
            for name, held in zip(table.INPUTS, self._inputs_held):
                if name in invalid:
                    setattr(joint, name, held)
            fresh = joint.outputs()
        finally:
            for name, value in zip(table.INPUTS, current):
                setattr(joint, name, value)
        return tuple(live[i] if dependencies & invalid else fresh[i]
                     for i, dependencies in enumerate(_OUTPUT_DEPENDENCIES))

    def _get_flat(self, indices):
        """Values at flat indices; raises IndexError for an index out of range."""
        outputs = self._outputs or self._current_outputs()
        if indices == ALL_OUTPUTS:
            return list(outputs)
        joint = self._joint
        return [outputs[i - FIRST_OUTPUT] if i >= FIRST_OUTPUT else getattr(joint, KNOWN[i])
                for i in indices]

    def _set_flat(self, indices, values, setter: str):
        """Set inputs and parameters by flat index; anything else is reported
        (as an error of `setter`) and ignored."""
        try:
            joint = self._joint
            if indices == ALL_INPUTS:
                for name, value in zip(table.INPUTS, values):
                    setattr(joint, name, float(value))
                self._outputs = None
                self._inputs_checked = False
                return
            parameters_changed = False
            for i, value in zip(indices, values):
                if not 0 <= i < FIRST_OUTPUT:
                    self._report(f"{setter} on {self._name_of(i)} ignored: only inputs and "
                                 f"parameters can be set", self._STATUS.error)
                elif i in INPUT_INDICES:
                    setattr(joint, KNOWN[i], float(value))
                elif self._initialized:
                    self._report(f"parameter {KNOWN[i]} = {value!r} ignored: fixed "
                                 f"parameters cannot change after initialization",
                                 self._STATUS.error)
                else:
                    setattr(joint, KNOWN[i], float(value))
                    parameters_changed = True
            if parameters_changed:
                self._restart()        # outputs in initialization mode see them at once
            self._outputs = None
            self._inputs_checked = False
        except Exception as error:
            self._fault(setter, error)

    @staticmethod
    def _name_of(index):
        return NAMES[index] if 0 <= index < len(NAMES) else f"value reference {index}"

    # --- FMU state -----------------------------------------------------------

    def _get_fmu_state(self):
        try:
            return {"joint": self._joint.state(), "start_time": self._start_time,
                    "initialized": self._initialized,
                    "outputs_held": list(self._outputs_held),
                    "inputs_held": list(self._inputs_held)}
        except Exception as error:
            self._fault(f"{self._API}GetFMU{self._STATE}", error)
            return {"invalid_state": f"{self._API}GetFMU{self._STATE} failed: {error}"}

    def _set_fmu_state(self, state):
        try:
            if "invalid_state" in state:
                raise ValueError(state["invalid_state"])
            held_outputs = tuple(float(v) for v in state["outputs_held"])
            held_inputs = tuple(float(v) for v in state["inputs_held"])
            if len(held_outputs) != len(table.OUTPUTS) or len(held_inputs) != len(table.INPUTS):
                raise ValueError("the state is from another version of the FMU")
            self._joint.restore(state["joint"])           # all or nothing
            self._start_time = float(state["start_time"])
            self._initialized = bool(state["initialized"])
            self._outputs_held, self._inputs_held = held_outputs, held_inputs
        except Exception as error:
            self._report(f"{self._API}SetFMU{self._STATE} ignored, the joint keeps its state: "
                         f"{type(error).__name__}: {error}", self._STATUS.error)
        finally:
            self._outputs = None
            self._inputs_checked = False

    # Class methods: both loaders call these on the class, not on an instance.
    @classmethod
    def _fmu_state_to_bytes(cls, state):
        try:
            return json.dumps(state).encode("utf-8")
        except Exception as error:
            return json.dumps({"invalid_state": f"serialization failed: {error}"}).encode()

    @classmethod
    def _fmu_state_from_bytes(cls, data):
        # Returning a marked state instead of raising: the set-state call then says why.
        try:
            state = json.loads(data.decode("utf-8"))
            if not isinstance(state, dict):
                raise ValueError("not a serialized UniversalJoint state")
            return state
        except Exception as error:
            return {"invalid_state": f"{cls._API}DeSerializeFMU{cls._STATE} got no valid "
                                     f"state: {error}"}
