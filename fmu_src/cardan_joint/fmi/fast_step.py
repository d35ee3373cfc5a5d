"""The one-call step: what the native loader calls once per doStep instead of
setReal, doStep and getReal (issue 21). This docstring is the protocol the
loader's C side follows.

Values. Per instance the loader owns two arrays of C doubles, sized and indexed
by `fast_layout()` (a class method: `References.layout`):
- known[known_size]: flat index i in slot i: inputs (0 to inputs - 1), then
  parameters (inputs to known_size - 1);
- outputs[outputs]: flat index first_output + k in slot k.
Flat indices are the FMI 2 value references; an FMI 3 loader maps its value
references onto them as `slave3._FLAT` does (time and arrays aside).
Values cross as tuples of floats, in slot order: the loader passes the inputs
(known[0:inputs]) as a tuple and converts what comes back itself, through the
C API (a float subclass or an int as float() converts it).

Generated step (docs/codegen.md). A runtime built with the model's step in C
calls fast_state_size() once: from then on the slave hands over, after every
value of `known`, the model's step state (`step_state()`: state_size floats)
and each output's armed watch limit (`outputs` floats, inf where none is
armed), and takes the state back with fast_sync. The runtime takes each step
it can in C: arguments (t, h, state, known), results (state, the moved inputs,
outputs). A step C does not take goes to fast_step, as without the generated
step. A step taken in C with an output past its limit (|value| > limit) is
handed over at once (fast_sync, then fast_watch): the slave warns once, as
after a step in Python.

Calls return a status (ok 0, warning 1, discard 2, error 3: the FMI version's
own IntEnum, or a plain int) or a tuple (status, values, ...) of a status and
tuples of floats, whose values, in order, the loader writes into its arrays.
Each call logs through the slave as any other call does; the loader forwards
the log queue after it:
- fast_state_size() -> int: the step state's size (0: the model has none);
  from then on fast_store and fast_step give the state after their values.
- fast_store() -> (ok, known[, state, limits]): every input and parameter. Call it after
  instantiation and after every call into the slave that can change them: a
  setReal forwarded to Python, exitInitializationMode, set or deserialized FMU
  state, reset.
- fast_load(inputs) -> status: takes the inputs (not the parameters), as a
  setReal of every input would. Call it before every other call into the
  slave when an input was written since the last fast_* call (FMU state get,
  a forwarded setReal, terminate...), so the slave sees the host's inputs.
- fast_sync(t, state, inputs, outputs) -> status: the model as the generated
  steps left it: clock t, its step state, the inputs and outputs of the last
  step (held for getReal, as fast_step holds them). Call it before any other
  call into the slave once a step was taken in C.
- fast_watch() -> (ok, limits) | error: after a fast_sync of a step whose
  output passed its limit: warns of each output past its own (logWatch), once,
  and gives the limits still armed.
- fast_step(t, h, inputs) -> (ok, outputs, inputs[, state]) | status: takes the
  inputs, steps; when taken, every output and then the inputs the step moved
  (speed, bend angle and rate advance over a step: a later getReal of them, or
  the next step, reads the moved value). On error (refused: the slave keeps
  its state and has logged variable, value, limit and time; or a fault): a
  bare status, nothing to write.
- fast_outputs(inputs, read=None) -> (ok | warning, outputs) | error: takes
  the inputs and gives every output without stepping; `read` is the getReal's
  flat indices, a tuple of ints in order (None: every output). ok: the outputs
  are current until the next input write or call into the slave; warning: an
  input or parameter is invalid and the outputs that depend on it are held at
  the last valid inputs; the slave has warned if `read` holds one of them, as
  getReal warns only then, and again at every such read, so the loader keeps
  them stale (and answers fmi2OK, as getReal does); error: a fault, logged.

Slave. The runtime constructs the slave itself (both FMI versions) and uses
that object; a slave without these methods keeps plain calls. Its `log_queue`
list is made once (pythonfmu's `__init__`) and only appended to: the loader
holds that list and drains it whenever it holds a message (a slave that bound
a new list would have its messages forwarded only at its next plain call).

In C. setReal of inputs only: write known, mark outputs stale. Any other
setReal: fast_load if needed, forward to Python, fast_store. getReal: if the
outputs are stale, fast_outputs(inputs, read) first (even for a read of inputs
only: getReal evaluates the outputs whatever it is asked, and warns if an output
read is held); then known and
outputs serve every index below first_output + outputs, anything else is
forwarded (the slave reports it). doStep: fast_step; outputs fresh on ok,
stale otherwise.
"""

from collections.abc import Callable
from typing import Any

from ..framework.api import Stepped
from ..framework.watches import any_passed
from .references import References


class FastStep:
    """Mixed into `core.SlaveCore`, whose state and helpers these are."""

    _refs: References
    table: Any
    _STATUS: Any
    _model: Stepped
    _outputs: tuple | None
    _inputs_checked: bool
    _inputs_held: tuple
    _step: Callable[[float, float], Any]
    _refused: Callable[[Any, float, float], Any]
    _current_outputs: Callable[[Any], tuple]
    _fault: Callable[[str, BaseException], None]
    _armed: Any
    _watch: Callable[[tuple], None]
    _watch_limits: Callable[[], tuple]
    # fast_state_size() was called: replies carry the model's step state.
    _state_exchange = False

    @classmethod
    def fast_layout(cls) -> dict:
        """The buffers' layout, for the loader to size and index its arrays."""
        return cls._refs.layout()

    def fast_load(self, inputs) -> int:
        """Take every input, as setReal of all inputs does (parameters are not
        taken: they are set through setReal, see the layout)."""
        try:
            self._take_inputs(inputs)
            return self._STATUS.ok
        except Exception as error:
            self._fault("fast_load", error)
            return self._STATUS.error

    def _take_inputs(self, inputs) -> None:
        self._model.set_inputs(inputs)
        self._outputs = None
        self._inputs_checked = False

    def fast_store(self):
        """Every input and parameter, for the loader's known array: at
        instantiation and after anything that changes them in Python (a
        parameter set, an FMU state set, a reset); then the step state."""
        try:
            known = self._refs.known_of(self._model)
            if self._state_exchange:
                state = tuple(self._model.step_state())
                return self._STATUS.ok, known, state, self._watch_limits()
            return self._STATUS.ok, known
        except Exception as error:
            self._fault("fast_store", error)
            return self._STATUS.error

    def fast_state_size(self) -> int:
        """The model's step state's size, handed over from now on (0: none)."""
        try:
            step_state = getattr(self._model, "step_state", None)
            size = len(step_state()) if step_state else 0
            self._state_exchange = size > 0
            return size
        except Exception as error:
            self._fault("fast_state_size", error)
            return 0

    def fast_sync(self, current_time, state, inputs, outputs):
        """The model where the generated steps left it: `fast_step`'s taken path
        with the step's results (so every later call sees what a step in Python
        would have left)."""
        try:
            model: Any = self._model
            model.set_step_state(state)
            model.set_inputs(inputs)
            model.time = current_time
            self._outputs = self._outputs_held = outputs
            self._inputs_held = inputs
            self._inputs_checked = True
            return self._STATUS.ok
        except Exception as error:
            self._fault("fast_sync", error)
            return self._STATUS.error

    def fast_watch(self):
        """A step taken in C passed an armed watch (the slave was synced): warn
        once, as `fast_step` does after a step in Python; the limits left."""
        try:
            if self._armed:
                self._watch(self._outputs)
            return self._STATUS.ok, self._watch_limits()
        except Exception as error:
            self._fault("fast_watch", error)
            return self._STATUS.error

    def fast_step(self, current_time, step_size, inputs):
        """The inputs, one step; (ok, every output, the moved inputs) when the
        step is taken, otherwise the status of the refusal or fault."""
        try:
            model = self._model
            # The model's step takes the inputs, steps and evaluates its outputs once.
            result = model.run(current_time, step_size, inputs)
            if result.__class__ is not tuple:
                self._outputs = None
                self._inputs_checked = False
                return self._refused(result, current_time, step_size)
            # A taken step moves the inputs that are polynomial over it (the speed,
            # the bend angle and rate): getReal of an input reads the moved value,
            # and the next step starts from it.
            outputs, moved = result
            self._outputs = self._outputs_held = outputs
            self._inputs_held = moved
            self._inputs_checked = True
            armed = self._armed  # watched limits, checked here, logged once (fmi/watching.py)
            if armed and any_passed(armed, outputs):
                self._watch(outputs)
            state = (tuple(model.step_state()),) if self._state_exchange else ()
            return self._STATUS.ok, outputs, moved, *state
        except Exception as error:
            self._fault("fast_step", error)
            return self._STATUS.error

    def fast_outputs(self, inputs, read=None):
        """The inputs, then every output without stepping (a read after a write of
        an input: direct feedthrough); `read`: the flat indices getReal reads."""
        try:
            self._take_inputs(inputs)
            outputs = tuple(self._current_outputs(read))
            # Held outputs are not cached (`_current_outputs`): the next read
            # re-evaluates and warns again, as getReal does.
            held = self._outputs is None
            return (self._STATUS.warning if held else self._STATUS.ok), outputs
        except Exception as error:
            self._fault("fast_outputs", error)
            return self._STATUS.error
