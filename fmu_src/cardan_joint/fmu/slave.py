"""The pythonfmu slave: maps FMI variables onto `physics.CardanJoint`.

No equation lives here. What does live here is the FMI plumbing that pythonfmu
0.7.0 gets wrong for a robust component: any Python exception reaching its C
layer becomes fmi2Fatal, so every method it calls catches everything; a
refused step returns False (fmi2Discard) with the joint untouched; the
complete state (including the revolution counter) is saved for
fmi2GetFMUstate; and every problem is logged (the FMU's native loader makes
sure it reaches the host, see `cardan_joint.native`).
"""

import json
import math
from operator import attrgetter

from pythonfmu import Fmi2Causality, Fmi2Slave, Fmi2Variability, Real
from pythonfmu.default_experiment import DefaultExperiment
from pythonfmu.enums import Fmi2Initial, Fmi2Status

from .. import __version__
from .. import variables as table
from ..physics.model import CardanJoint
from .model_description import complete

class _References:
    """Value references of one variable table: inputs, then parameters, then outputs."""

    def __init__(self, table):
        self.known = table.INPUTS + table.PARAMETERS
        self.names = self.known + table.OUTPUTS
        self.first_output = len(self.known)
        assert tuple(v.name for v in table.VARIABLES) == self.names, \
            "the slave's value references assume inputs, then parameters, then outputs"
        assert table.OUTPUTS[0] == "input_angle", "held outputs keep the first one, the state, live"
        self.inputs = range(len(table.INPUTS))
        self.nan_outputs = (math.nan,) * len(table.OUTPUTS)
        self.output_dependencies = tuple(frozenset(table.BY_NAME[n].depends_on)
                                         for n in table.OUTPUTS)
        self.inputs_of = attrgetter(*table.INPUTS)
        # What FMPy and most masters pass every step: all inputs, all outputs, in order.
        self.all_inputs = list(self.inputs)
        self.all_outputs = list(range(self.first_output, len(self.names)))


class CardanJointSlave(Fmi2Slave):
    author = "Cardan joint FMU team"
    license = "MIT"
    version = __version__
    description = ("Exact Cardan (Hooke) universal joint: output shaft motion, crosspiece "
                   "orientation and dynamics, input torque and secondary couples")
    default_experiment = DefaultExperiment(start_time=0.0, stop_time=2.0, step_size=1e-3)
    log_categories = {
        "logStatusWarning": "Warnings: outputs held at the last valid inputs.",
        "logStatusDiscard": "Refused steps: the variable, its value, the limit and the time.",
        "logStatusError": "Errors: invalid parameters, calls FMI does not allow, internal faults.",
        "logStatusFatal": "Not used: the FMU never ends in fmi2Fatal on its own.",
        "logAll": "All messages.",
    }
    # Start values that differ from the table's, written in by the build script.
    start_overrides: dict = {}
    # The model's variable table; a subclass for another model sets it (and
    # `_new_model`), the value references follow.
    table = table
    _refs = _References(table)

    def __init_subclass__(cls, **kwargs):
        super().__init_subclass__(**kwargs)
        cls._refs = _References(cls.table)

    def _new_model(self):
        """The physics object the slave maps its variables onto."""
        return CardanJoint(**self.start_overrides)

    def _initialization_warnings(self):
        """Messages logged as warnings when initialization ends (none for the joint)."""
        return ()

    def __init__(self, **kwargs):
        super().__init__(**kwargs)
        refs = self._refs
        self._joint = self._new_model()
        self._start_time = 0.0
        self._initialized = False
        self._outputs = None            # cached outputs; None = recompute on next read
        self._inputs_checked = False
        self._outputs_held, self._inputs_held = refs.nan_outputs, refs.inputs_of(self._joint)
        if not (self._joint.parameter_fault or self._joint.input_problem()):
            self._outputs_held = self._joint.outputs()
        for name in refs.names:
            self._register(self.table.BY_NAME[name])

    def _register(self, variable):
        causality = Fmi2Causality[variable.causality]
        initial = Fmi2Initial[variable.initial] if variable.initial else None
        reference = len(self.vars)
        self.register_variable(Real(
            variable.name, causality=causality, description=variable.description,
            variability=Fmi2Variability[variable.variability], initial=initial,
            getter=lambda: self.get_real([reference])[0],
            setter=lambda value: self.set_real([reference], [value])))

    def to_xml(self, model_options=None):
        options = {"canGetAndSetFMUstate": True, "canSerializeFMUstate": True,
                   **(model_options or {})}
        return complete(super().to_xml(options), self.table)

    # --- messages ------------------------------------------------------------

    def _report(self, message: str, status: Fmi2Status) -> None:
        # No stderr here: the FMU's native loader hands every message to the host's
        # logger (warnings and refusals even with debug logging off), or to stderr
        # when the host gave no logger or $CARDAN_JOINT_FMU_STDERR asks for it.
        self.log(message, status)

    def _fault(self, where: str, error: BaseException) -> None:
        try:
            self._report(f"internal error in {where}: {type(error).__name__}: {error}",
                         Fmi2Status.error)
        except Exception:
            pass

    # --- life cycle ----------------------------------------------------------

    def setup_experiment(self, start_time, stop_time=None, tolerance=None):
        try:
            self._start_time = float(start_time)
            self._restart()
        except Exception as error:
            self._fault("setup_experiment", error)

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
                self._report(f"{problem.message}; every step will be refused until it is fixed",
                             Fmi2Status.error)
            for message in self._initialization_warnings():
                self._report(message, Fmi2Status.warning)
        except Exception as error:
            self._fault("exit_initialization_mode", error)

    def do_step(self, current_time, step_size):
        try:
            joint = self._joint
            time = joint.time
            joint.time = current_time
            problem = joint.step(step_size)
            if problem:
                joint.time = time
                self._report(f"{problem.message}; step of {step_size!r} s refused, the joint "
                             f"stays at t = {current_time!r} s", Fmi2Status.discard)
                return False
            self._outputs = None
            self._inputs_checked = True
            return True
        except Exception as error:
            self._fault("do_step", error)
            return False

    # --- values --------------------------------------------------------------

    def _current_outputs(self):
        joint = self._joint
        if not self._inputs_checked:
            problem = joint.parameter_fault or joint.input_problem()
            if problem:
                self._report(f"{problem.at(joint.time).message}; outputs that depend on it "
                             f"are held at the last valid inputs", Fmi2Status.warning)
                return self._held_outputs(joint)
            self._inputs_checked = True
        self._outputs = self._outputs_held = joint.outputs()
        self._inputs_held = self._refs.inputs_of(joint)
        return self._outputs

    def _held_outputs(self, joint):
        """Outputs with invalid inputs: each output that depends on an invalid input
        keeps its last valid value, the others (and the input angle, the state)
        follow the valid inputs, as the declared dependencies promise."""
        live = (joint.input_angle,) + self._outputs_held[1:]
        if joint.parameter_fault:
            return live
        invalid = joint.invalid_inputs()
        inputs = self.table.INPUTS
        current = self._refs.inputs_of(joint)
        try:
            for name, held in zip(inputs, self._inputs_held):
                if name in invalid:
                    setattr(joint, name, held)
            fresh = joint.outputs()
        finally:
            for name, value in zip(inputs, current):
                setattr(joint, name, value)
        return tuple(live[i] if dependencies & invalid else fresh[i]
                     for i, dependencies in enumerate(self._refs.output_dependencies))

    def get_real(self, vrs):
        try:
            outputs = self._outputs or self._current_outputs()
            refs = self._refs
            if vrs == refs.all_outputs:
                return list(outputs)
            joint, first = self._joint, refs.first_output
            return [outputs[vr - first] if vr >= first else getattr(joint, refs.known[vr])
                    for vr in vrs]
        except Exception as error:
            bad = [vr for vr in vrs if not 0 <= vr < len(self._refs.names)]
            if bad:
                self._report(f"get_real: no Real variable has value reference {bad[0]}",
                             Fmi2Status.error)
            else:
                self._fault("get_real", error)
            return [math.nan] * len(vrs)

    def set_real(self, vrs, values):
        try:
            joint, refs = self._joint, self._refs
            known = refs.known
            if vrs == refs.all_inputs:
                for name, value in zip(self.table.INPUTS, values):
                    setattr(joint, name, float(value))
                self._outputs = None
                self._inputs_checked = False
                return
            parameters_changed = False
            for vr, value in zip(vrs, values):
                if not 0 <= vr < refs.first_output:
                    self._report(f"set_real on {self._name_of(vr)} ignored: only inputs and "
                                 f"parameters can be set", Fmi2Status.error)
                elif vr in refs.inputs:
                    setattr(joint, known[vr], float(value))
                elif self._initialized:
                    self._report(f"parameter {known[vr]} = {value!r} ignored: fixed "
                                 f"parameters cannot change after initialization",
                                 Fmi2Status.error)
                else:
                    setattr(joint, known[vr], float(value))
                    parameters_changed = True
            if parameters_changed:
                self._restart()        # outputs in initialization mode see them at once
            self._outputs = None
            self._inputs_checked = False
        except Exception as error:
            self._fault("set_real", error)

    def _name_of(self, vr):
        names = self._refs.names
        return names[vr] if 0 <= vr < len(names) else f"value reference {vr}"

    # The FMU has Real variables only; pythonfmu's typed accessors would raise
    # (fmi2Fatal) on any other call, so these refuse politely instead.
    def _no_such_variables(self, kind, vrs):
        self._report(f"the FMU has no {kind} variables (value references {list(vrs)})",
                     Fmi2Status.error)

    def get_integer(self, vrs):
        self._no_such_variables("Integer", vrs)
        return [0] * len(vrs)

    def get_boolean(self, vrs):
        self._no_such_variables("Boolean", vrs)
        return [False] * len(vrs)

    def get_string(self, vrs):
        self._no_such_variables("String", vrs)
        return [""] * len(vrs)

    def set_integer(self, vrs, values):
        self._no_such_variables("Integer", vrs)

    def set_boolean(self, vrs, values):
        self._no_such_variables("Boolean", vrs)

    def set_string(self, vrs, values):
        self._no_such_variables("String", vrs)

    # --- FMU state -----------------------------------------------------------

    def _get_fmu_state(self):
        try:
            return {"joint": self._joint.state(), "start_time": self._start_time,
                    "initialized": self._initialized,
                    "outputs_held": list(self._outputs_held),
                    "inputs_held": list(self._inputs_held)}
        except Exception as error:
            self._fault("fmi2GetFMUstate", error)
            return {"invalid_state": f"fmi2GetFMUstate failed: {error}"}

    def _set_fmu_state(self, state):
        try:
            if "invalid_state" in state:
                raise ValueError(state["invalid_state"])
            held_outputs = tuple(float(v) for v in state["outputs_held"])
            held_inputs = tuple(float(v) for v in state["inputs_held"])
            if (len(held_outputs) != len(self.table.OUTPUTS)
                    or len(held_inputs) != len(self.table.INPUTS)):
                raise ValueError("the state is from another version of the FMU")
            self._joint.restore(state["joint"])           # all or nothing
            self._start_time = float(state["start_time"])
            self._initialized = bool(state["initialized"])
            self._outputs_held, self._inputs_held = held_outputs, held_inputs
        except Exception as error:
            self._report(f"fmi2SetFMUstate ignored, the joint keeps its state: "
                         f"{type(error).__name__}: {error}", Fmi2Status.error)
        finally:
            self._outputs = None
            self._inputs_checked = False

    @staticmethod
    def _fmu_state_to_bytes(state):
        try:
            return json.dumps(state).encode("utf-8")
        except Exception as error:
            return json.dumps({"invalid_state": f"serialization failed: {error}"}).encode()

    @staticmethod
    def _fmu_state_from_bytes(data):
        # Returning a marked state instead of raising: fmi2SetFMUstate then says why.
        try:
            state = json.loads(data.decode("utf-8"))
            if not isinstance(state, dict):
                raise ValueError("not a serialized FMU state of this project")
            return state
        except Exception as error:
            return {"invalid_state": f"fmi2DeSerializeFMUstate got no valid state: {error}"}
