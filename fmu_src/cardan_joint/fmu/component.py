"""The pythonfmu slave for a small stepped model (`physics.Motor`, `physics.Load`).

Maps the model's table onto FMI variables: inputs settable at any time,
parameters until initialization ends, outputs computed from the model. A step
the model refuses returns False (fmi2Discard) with the model untouched and a
message naming the variable, its value, the limit and the time; outputs read
with an unusable input are held at their last valid values, with a warning.
"""

import math

from pythonfmu.default_experiment import DefaultExperiment
from pythonfmu.enums import Fmi2Status

from .. import __version__
from .base import TableSlave


class ComponentSlave(TableSlave):
    author = "Cardan joint FMU team"
    license = "MIT"
    version = __version__
    default_experiment = DefaultExperiment(start_time=0.0, stop_time=2.0, step_size=1e-3)
    log_categories = {
        "logStatusWarning": "Warnings: outputs held at the last valid inputs.",
        "logStatusDiscard": "Refused steps: the variable, its value, the limit and the time.",
        "logStatusError": "Errors: invalid parameters, calls FMI does not allow, internal faults.",
        "logAll": "All messages.",
    }
    model_class = None          # the physics model class; its `table` drives everything
    start_overrides: dict = {}  # start values that differ from the table's (written by the build)

    def __init__(self, **kwargs):
        super().__init__(**kwargs)
        self.table = table = self.model_class.table
        self._model = self.model_class(**self.start_overrides)
        self._names = table.INPUTS + table.PARAMETERS + table.OUTPUTS
        self._first_output = len(table.INPUTS) + len(table.PARAMETERS)
        self._start_time = 0.0
        self._initialized = False
        self._held = (math.nan,) * len(table.OUTPUTS)
        if not (self._model.parameter_fault or self._model.input_problem()):
            self._held = self._model.outputs()
        for name in self._names:
            self._register(table.BY_NAME[name])

    # --- life cycle ----------------------------------------------------------

    def setup_experiment(self, start_time, stop_time=None, tolerance=None):
        try:
            self._start_time = float(start_time)
            self._model.start(self._start_time)
        except Exception as error:
            self._fault("setup_experiment", error)

    def exit_initialization_mode(self):
        try:
            self._model.start(self._start_time)
            self._initialized = True
            if self._model.parameter_fault:
                self._report(f"{self._model.parameter_fault}; every step will be refused "
                             f"until it is fixed", Fmi2Status.error)
        except Exception as error:
            self._fault("exit_initialization_mode", error)

    def do_step(self, current_time, step_size):
        try:
            model = self._model
            time = model.time
            model.time = current_time
            problem = model.step(step_size)
            if problem:
                model.time = time
                self._report(f"t = {current_time!r} s: {problem}; step of {step_size!r} s "
                             f"refused, the {self.modelName} stays at t = {current_time!r} s",
                             Fmi2Status.discard)
                return False
            return True
        except Exception as error:
            self._fault("do_step", error)
            return False

    # --- values --------------------------------------------------------------

    def _outputs(self):
        model = self._model
        problem = model.parameter_fault or model.input_problem()
        if problem:
            self._report(f"t = {model.time!r} s: {problem}; outputs are held at the last "
                         f"valid inputs", Fmi2Status.warning)
            return self._held
        self._held = model.outputs()
        return self._held

    def get_real(self, vrs):
        try:
            first = self._first_output
            outputs = self._outputs() if any(vr >= first for vr in vrs) else ()
            return [outputs[vr - first] if vr >= first else getattr(self._model, self._names[vr])
                    for vr in vrs]
        except Exception as error:
            bad = [vr for vr in vrs if not 0 <= vr < len(self._names)]
            if bad:
                self._report(f"get_real: no Real variable has value reference {bad[0]}",
                             Fmi2Status.error)
            else:
                self._fault("get_real", error)
            return [math.nan] * len(vrs)

    def set_real(self, vrs, values):
        try:
            model, n_inputs = self._model, len(self.table.INPUTS)
            parameters_changed = False
            for vr, value in zip(vrs, values):
                name = self._names[vr] if 0 <= vr < len(self._names) else f"value reference {vr}"
                if not 0 <= vr < self._first_output:
                    self._report(f"set_real on {name} ignored: only inputs and parameters can "
                                 f"be set", Fmi2Status.error)
                elif vr < n_inputs:
                    setattr(model, name, float(value))
                elif self._initialized:
                    self._report(f"parameter {name} = {value!r} ignored: fixed parameters "
                                 f"cannot change after initialization", Fmi2Status.error)
                else:
                    setattr(model, name, float(value))
                    parameters_changed = True
            if parameters_changed:
                model.start(self._start_time)     # outputs in initialization mode see them
        except Exception as error:
            self._fault("set_real", error)

    # --- FMU state -----------------------------------------------------------

    def _get_fmu_state(self):
        try:
            return {"model": self._model.state(), "start_time": self._start_time,
                    "initialized": self._initialized, "held": list(self._held)}
        except Exception as error:
            self._fault("fmi2GetFMUstate", error)
            return {"invalid_state": f"fmi2GetFMUstate failed: {error}"}

    def _set_fmu_state(self, state):
        try:
            if "invalid_state" in state:
                raise ValueError(state["invalid_state"])
            held = tuple(float(v) for v in state["held"])
            if len(held) != len(self.table.OUTPUTS):
                raise ValueError("the state is from another version of the FMU")
            self._model.restore(state["model"])           # all or nothing
            self._start_time = float(state["start_time"])
            self._initialized = bool(state["initialized"])
            self._held = held
        except Exception as error:
            self._report(f"fmi2SetFMUstate ignored, the {self.modelName} keeps its state: "
                         f"{type(error).__name__}: {error}", Fmi2Status.error)
