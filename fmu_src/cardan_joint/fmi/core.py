"""What every slave of this project shares, whatever the model and the FMI version.

No equation lives here: a slave maps its variables onto a physics object
(`_new_model()`: whatever the model folder's spec makes, see `binding`) with the
model API of `framework.api.Stepped`. This mixin keeps the behaviour around it:
the output cache, the outputs held while an input is invalid, the refused step
that leaves the model untouched, the parameters fixed after initialization and
the complete FMU state. It addresses variables by *flat index*, the position
in the class's variable `table` (inputs, parameters, outputs); each slave maps
its value references onto flat indices with its `_FLAT` table (`references`).

Both pythonfmu libraries turn any Python exception into a fatal status, so
every method here that a slave calls catches everything. A slave mixes this in
before its pythonfmu base and provides `_STATUS` (its status enumeration),
`_API` and `_STATE` (for messages naming FMI functions) and `_report`.
"""

from typing import Any

from .. import __version__
from ..framework.refusal import Refusal
from .fast_path import FastPath
from .fmu_state import FmuStates
from .references import References, ValueReferences
from .watching import Watching


def _readable(seconds: float) -> str:
    """A master's step sizes and clocks carry float noise (0.0010000000000000009):
    12 digits hide it, in the same style as the refusal's own exact values (1.0)."""
    return repr(float(f"{seconds:.12g}"))


class SlaveCore(ValueReferences, Watching, FmuStates, FastPath):
    author = "Cardan joint FMU team"
    license = "MIT"
    version = __version__
    description = ""  # the model's (its spec's, see binding.py)
    # Each slave makes its library's DefaultExperiment of these.
    experiment = {"start_time": 0.0, "stop_time": 2.0, "step_size": 1e-3}
    # Start values that differ from the table's, written in by the build script.
    start_overrides: dict = {}
    # The model's variable table; a model's slave sets it, `_new_model` and
    # `live_outputs` (the leading outputs that follow the model's state even
    # while inputs are invalid); the flat indices follow.
    table: Any = None
    live_outputs: tuple[str, ...] = ()
    owner = "model"  # what stays put in messages
    _refs: Any = None
    # Set by each FMI version's slave: its status enumeration, "fmi2"/"fmi3" and
    # "state"/"State" (for messages naming FMI functions).
    _STATUS: Any
    _API: str
    _STATE: str

    def _report(self, message: str, status, category: str | None = None) -> None:
        """Log `message` with `status` (each FMI version's slave says how)."""
        raise NotImplementedError

    def __init_subclass__(cls, **kwargs):
        super().__init_subclass__(**kwargs)
        if cls.table is not None:
            cls._refs = References(cls.table, cls.live_outputs)

    def _new_model(self):
        """The physics object the slave maps its variables onto."""
        raise NotImplementedError(f"{type(self).__name__} names no model")

    def _initialization_warnings(self):
        """Messages logged as warnings when initialization ends (none by default)."""
        return ()

    def _init_model(self):
        refs = self._refs
        self._model = self._new_model()
        self._start_time = 0.0
        self._initialized = False
        self._outputs = None  # cached outputs; None = recompute on next read
        self._inputs_checked = False
        self._outputs_held, self._inputs_held = refs.nan_outputs, self._model.inputs()
        if not (self._model.parameter_fault or self._model.input_problem()):
            self._outputs_held = self._model.outputs()

    def _fault(self, where: str, error: BaseException) -> None:
        try:
            self._report(
                f"internal error in {where}: {type(error).__name__}: {error}", self._STATUS.error
            )
        except Exception:
            pass

    # --- life cycle ----------------------------------------------------------

    def _restart(self):
        """Re-apply the start time and parameters (before initialization ends)."""
        self._model.start(self._start_time)
        self._outputs = None
        self._inputs_checked = False

    def exit_initialization_mode(self):
        try:
            self._restart()
            self._initialized = True
            self._rearm()
            problem = self._model.parameter_fault
            if problem:
                self._report(
                    f"{problem.message}; every step will be refused until it is fixed",
                    self._STATUS.error,
                )
            for message in self._initialization_warnings():
                self._report(message, self._STATUS.warning)
        except Exception as error:
            self._fault("exit_initialization_mode", error)

    def _step(self, current_time, step_size):
        """Take the step (the model's `run`); return the status: ok, or error
        (refused, the model as it was, or an internal fault; reported either way)."""
        try:
            model = self._model
            result = model.run(current_time, step_size, model.inputs())
            if isinstance(result, Refusal):
                return self._refused(result, current_time, step_size)
            outputs, moved = result
            self._taken(outputs, moved)
            if self._armed:
                self._watch(outputs)
            return self._STATUS.ok
        except Exception as error:
            self._fault("do_step", error)
            return self._STATUS.error

    def _taken(self, outputs, inputs):
        """After a taken step: its outputs, current and held for getReal, and the
        inputs after it (those polynomial over the step have moved: a getReal of
        one reads the moved value, and the next step starts from it)."""
        self._outputs = self._outputs_held = outputs
        self._inputs_held = inputs
        self._inputs_checked = True

    def _refused(self, problem, current_time, step_size):
        """Report a refused step (the model as it was) at the status it returns."""
        self._report(
            f"{problem.message}; step of {_readable(step_size)} s refused, the "
            f"{self.owner} stays at t = {_readable(current_time)} s",
            self._STATUS.error,
        )
        return self._STATUS.error

    # --- values --------------------------------------------------------------

    def _current_outputs(self, read=None):
        """Every output, held while a value is invalid; warns if an output `read` is."""
        model = self._model
        if not self._inputs_checked:
            problem = model.parameter_fault or model.input_problem()
            if problem:
                outputs, held = self._held_outputs(model)
                if read is None or any(i - self._refs.first_output in held for i in read):
                    self._report(
                        f"{problem.at(model.time).message}; outputs that depend on it "
                        f"are held at the last valid inputs",
                        self._STATUS.warning,
                    )
                return outputs
            self._inputs_checked = True
        self._outputs = self._outputs_held = model.outputs()
        self._inputs_held = model.inputs()
        return self._outputs

    def _held_outputs(self, model):
        """(outputs, positions held) with invalid values: an output that depends on an
        invalid input (any but the live outputs, the state, for a parameter) keeps its
        last valid value; the others follow the valid inputs, as their dependencies say."""
        live = (
            tuple(getattr(model, name) for name in self.live_outputs)
            + self._outputs_held[len(self.live_outputs) :]
        )
        if model.parameter_fault:
            return live, range(len(self.live_outputs), len(live))
        invalid = model.invalid_inputs()
        current = model.inputs()
        try:
            model.set_inputs(
                tuple(
                    held if name in invalid else value
                    for name, held, value in zip(self.table.INPUTS, self._inputs_held, current)
                )
            )
            fresh = model.outputs()
        finally:
            model.set_inputs(current)
        held = {i for i, depends in enumerate(self._refs.output_dependencies) if depends & invalid}
        return tuple(live[i] if i in held else value for i, value in enumerate(fresh)), held

    def _get_flat(self, indices):
        """Values at flat indices; raises IndexError for an index out of range."""
        outputs = self._outputs or self._current_outputs(indices)
        refs = self._refs
        if indices == refs.all_outputs:
            return list(outputs)
        model, first = self._model, refs.first_output
        return [
            outputs[i - first] if i >= first else getattr(model, refs.known[i]) for i in indices
        ]

    def _set_flat(self, indices, values, setter: str):
        """Set inputs and parameters by flat index; anything else is reported
        (as an error of `setter`) and ignored."""
        try:
            model, refs = self._model, self._refs
            known = refs.known
            if indices == refs.all_inputs:
                model.set_inputs(tuple(map(float, values)))
                self._outputs = None
                self._inputs_checked = False
                return
            parameters_changed = False
            for i, value in zip(indices, values):
                if not 0 <= i < refs.first_output:
                    self._report(
                        f"{setter} on {self._name_of(i)} ignored: only inputs and "
                        f"parameters can be set",
                        self._STATUS.error,
                    )
                elif i in refs.inputs:
                    setattr(model, known[i], float(value))
                elif self._initialized:
                    self._report(
                        f"parameter {known[i]} = {value!r} ignored: fixed "
                        f"parameters cannot change after initialization",
                        self._STATUS.error,
                    )
                else:
                    setattr(model, known[i], float(value))
                    parameters_changed = True
            if parameters_changed:
                self._restart()  # outputs in initialization mode see them at once
            self._outputs = None
            self._inputs_checked = False
        except Exception as error:
            self._fault(setter, error)

    def _name_of(self, index):
        names = self._refs.names
        return names[index] if 0 <= index < len(names) else f"value reference {index}"
