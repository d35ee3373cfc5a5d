"""The pythonfmu slave: maps FMI variables onto `physics.CardanJoint`.

No equation lives here. What does live here is the FMI plumbing that pythonfmu
0.7.0 gets wrong for a robust component: no Python exception may reach its C
layer (it turns into fmi2Fatal), a refused step returns False (fmi2Discard)
with the joint untouched, the complete state (including the revolution
counter) is saved for fmi2GetFMUstate, and every refusal is also written to
stderr because pythonfmu drops log messages unless debug logging is on.
"""

import math
import sys

from pythonfmu import Fmi2Causality, Fmi2Slave, Fmi2Variability, Real
from pythonfmu.enums import Fmi2Initial, Fmi2Status
from pythonfmu.default_experiment import DefaultExperiment

from .. import __version__
from .. import variables as table
from ..physics.model import CardanJoint
from .model_description import complete

_KNOWN = table.INPUTS + table.PARAMETERS
_FIRST_OUTPUT = len(_KNOWN)
assert tuple(v.name for v in table.VARIABLES) == _KNOWN + table.OUTPUTS, \
    "the slave's value references assume inputs, then parameters, then outputs"
assert table.OUTPUTS[0] == "input_angle", "held outputs keep the first one, the state, live"
_INPUT_REFERENCES = range(len(table.INPUTS))
_NAN_OUTPUTS = (math.nan,) * len(table.OUTPUTS)


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

    def __init__(self, **kwargs):
        super().__init__(**kwargs)
        self._joint = CardanJoint(**self.start_overrides)
        self._start_time = 0.0
        self._initialized = False
        self._outputs = None            # cached outputs; None = recompute on next read
        self._outputs_held = _NAN_OUTPUTS if self._joint.parameter_problem() else self._joint.outputs()
        self._inputs_checked = False
        self._last_message = None
        for name in table.INPUTS + table.PARAMETERS + table.OUTPUTS:
            self._register(table.BY_NAME[name])

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
        return complete(super().to_xml(options))

    # --- messages ------------------------------------------------------------

    def _report(self, message: str, status: Fmi2Status) -> None:
        self.log(message, status)
        if message != self._last_message:
            # pythonfmu forwards log messages only with debug logging on, so a user
            # of plain fmpy.simulate_fmu would never learn why the run stopped.
            sys.stderr.write(f"[{self.modelName} {self.instance_name}] "
                             f"{status.name.upper()}: {message}\n")
            sys.stderr.flush()
            self._last_message = message

    def _fault(self, where: str, error: BaseException) -> None:
        self._report(f"internal error in {where}: {type(error).__name__}: {error}",
                     Fmi2Status.error)

    # --- life cycle ----------------------------------------------------------

    def setup_experiment(self, start_time, stop_time=None, tolerance=None):
        self._start_time = start_time

    def exit_initialization_mode(self):
        try:
            self._joint.start(self._start_time)
            self._outputs = None
            self._initialized = True
            problem = self._joint.parameter_problem()
            if problem:
                self._report(f"{problem}; every step will be refused until it is fixed",
                             Fmi2Status.error)
        except Exception as error:
            self._fault("exit_initialization_mode", error)

    def do_step(self, current_time, step_size):
        try:
            joint = self._joint
            joint.time = current_time
            problem = joint.step(step_size)
            if problem:
                self._report(f"t = {current_time!r} s: {problem}; step of {step_size!r} s "
                             f"refused, the joint stays at t = {current_time!r} s",
                             Fmi2Status.discard)
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
            problem = joint.parameter_problem() or joint.input_problem()
            if problem:
                self._report(f"t = {joint.time!r} s: {problem}; outputs are held at the "
                             f"last valid inputs", Fmi2Status.warning)
                # The input angle is state, not a function of the inputs: always current.
                return (joint.input_angle,) + self._outputs_held[1:]
            self._inputs_checked = True
        self._outputs = self._outputs_held = joint.outputs()
        return self._outputs

    def get_real(self, vrs):
        try:
            outputs = self._outputs or self._current_outputs()
            joint = self._joint
            return [outputs[vr - _FIRST_OUTPUT] if vr >= _FIRST_OUTPUT
                    else getattr(joint, _KNOWN[vr]) for vr in vrs]
        except Exception as error:
            self._fault("get_real", error)
            return [math.nan] * len(vrs)

    def set_real(self, vrs, values):
        try:
            joint = self._joint
            for vr, value in zip(vrs, values):
                if vr >= _FIRST_OUTPUT or vr < 0:
                    self._report(f"set_real on {self._name_of(vr)} ignored: only inputs and "
                                 f"parameters can be set", Fmi2Status.error)
                elif vr not in _INPUT_REFERENCES and self._initialized:
                    self._report(f"parameter {_KNOWN[vr]} = {value!r} ignored: fixed "
                                 f"parameters cannot change after initialization",
                                 Fmi2Status.error)
                else:
                    setattr(joint, _KNOWN[vr], float(value))
            self._outputs = None
            self._inputs_checked = False
        except Exception as error:
            self._fault("set_real", error)

    @staticmethod
    def _name_of(vr):
        names = _KNOWN + table.OUTPUTS
        return names[vr] if 0 <= vr < len(names) else f"value reference {vr}"

    # --- FMU state -----------------------------------------------------------

    def _get_fmu_state(self):
        try:
            return {"joint": self._joint.state(), "start_time": self._start_time,
                    "initialized": self._initialized,
                    "outputs_held": list(self._outputs_held)}
        except Exception as error:
            self._fault("fmi2GetFMUstate", error)
            return {}

    def _set_fmu_state(self, state):
        try:
            self._joint.restore(state["joint"])
            self._start_time = state["start_time"]
            self._initialized = state["initialized"]
            self._outputs_held = tuple(state["outputs_held"])
            self._outputs = None
            self._inputs_checked = False
        except Exception as error:
            self._fault("fmi2SetFMUstate", error)
