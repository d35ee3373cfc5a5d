"""The pythonfmu slave for a small stepped model (`physics.Motor`, `physics.Load`).

Maps the model's table onto FMI variables: inputs settable at any time,
parameters until initialization ends, outputs computed from the model. A step
the model refuses returns False (fmi2Discard) with the model untouched and a
message naming the variable, its value, the limit and the time; outputs read
with an unusable input are held at their last valid values, with a warning.
"""

import math

from pythonfmu.enums import Fmi2Status

from .base import TableSlave


class ComponentSlave(TableSlave):
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
            problem = self._model.step(step_size, start_time=current_time)
            if problem:
                self._report(f"t = {current_time!r} s: {problem}; step of {step_size!r} s "
                             f"refused, the {self.modelName} stays at t = {current_time!r} s",
                             Fmi2Status.discard)
            return not problem
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
            return self._get_real_failed(vrs, error, len(self._names))

    def set_real(self, vrs, values):
        try:
            model, n_inputs = self._model, len(self.table.INPUTS)
            parameters_changed = False
            for vr, value in zip(vrs, values):
                name = self._names[vr] if 0 <= vr < len(self._names) else f"value reference {vr}"
                if self._write_permitted(vr, name, value, n_inputs, self._first_output):
                    setattr(model, name, float(value))
                    parameters_changed = parameters_changed or vr >= n_inputs
            if parameters_changed:
                model.start(self._start_time)     # outputs in initialization mode see them
        except Exception as error:
            self._fault("set_real", error)

    # --- FMU state -----------------------------------------------------------

    @property
    def _state_owner(self):
        return self.modelName

    def _state_parts(self):
        return {"model": self._model.state(), "held": list(self._held)}

    def _restore_parts(self, state):
        held = tuple(float(v) for v in state["held"])
        if len(held) != len(self.table.OUTPUTS):
            raise ValueError("the state is from another version of the FMU")
        self._model.restore(state["model"])           # all or nothing
        self._held = held
