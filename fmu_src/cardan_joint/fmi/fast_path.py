"""The slave's side of the runtime's fast path (fmi/native/fast_path.c): the
runtime keeps an instance's Real values in C arrays, serves setReal of inputs
and getReal from them, and runs the model's generated step on them
(docs/codegen.md); these methods keep the slave and the arrays in step. This
docstring is the protocol the runtime's C side follows.

Values. Per instance the runtime owns two arrays of C doubles, sized and indexed
by `fast_layout()` (a class method: `References.layout`):
- known[known_size]: flat index i in slot i: inputs (0 to inputs - 1), then
  parameters (inputs to known_size - 1);
- outputs[outputs]: flat index first_output + k in slot k.
Flat indices are positions in the model's variable table; `fast_flat` (the
slave's `_FLAT`, both FMI versions) maps each value reference onto them.
Values cross as tuples of floats, in slot order: the runtime passes the inputs
(known[0:inputs]) as a tuple and converts what comes back itself, through the
C API (a float subclass or an int as float() converts it).

Generated step. A runtime built with the model's step in C calls
fast_state_size() once: from then on the slave hands over, after the
outputs of `fast_store`, the model's step state (`step_state()`: state_size
floats) and each output's armed watch limit (`outputs` floats, inf where none
is armed), and takes the state back with fast_sync. The runtime takes each
step it can in C: arguments (t, h, state, known), results (state, the moved
inputs, outputs). A step C does not take (or every step, without a generated
step or with $CARDAN_JOINT_FMU_PYTHON_STEP=1) is the slave's plain do_step
(`core.SlaveCore._step`), in one call, fast_do_step, which takes the inputs
(as fast_load) and stores after it (as fast_store); fast_sync before it, as
before any other call into the slave. A step taken in C
with an output past its limit (|value| > limit) is handed over at once
(fast_sync, then fast_watch): the slave warns once, as after a step in Python.

Calls return a status (ok 0, warning 1, discard 2, error 3: the FMI version's
own IntEnum, or a plain int) or a tuple (status, values, ...) of a status and
tuples of floats, whose values, in order, the runtime writes into its arrays.
Each call logs through the slave as any other call does; the runtime forwards
the log queue after it:
- fast_state_size() -> int: the step state's size (0: the model has none);
  from then on fast_store gives the state and the limits after its values.
- fast_store() -> (ok, known, outputs[, state, limits]): every input and
  parameter, and the last valid outputs (`_outputs_held`: after a step taken
  in Python, the step's, which the runtime then serves). Call it after
  instantiation and after every other call into the slave (fast_do_step
  stores itself): a setReal forwarded to Python, exitInitializationMode, set
  or deserialized FMU state, reset.
- fast_load(inputs) -> status: takes the inputs (not the parameters), as a
  setReal of every input would. Call it before every other call into the
  slave (fast_do_step takes them itself) when an input was written since the
  last fast_* call (FMU state get, a forwarded setReal, terminate...), so the
  slave sees the host's inputs.
- fast_do_step(t, h, inputs=None) -> (do_step's result, fast_store's reply):
  fast_load(inputs) when given (an input was written since the last fast_*
  call), then do_step(t, h), then fast_store(); the result is read as the
  FMI version's do_step result is, the reply as fast_store's.
- fast_sync(t, state, inputs, outputs) -> status: the model as the generated
  steps left it: clock t, its step state, the inputs and outputs of the last
  step (held for getReal, as a step in Python holds them). Call it before any
  other call into the slave once a step was taken in C.
- fast_watch() -> (ok, limits) | error: after a fast_sync of a step whose
  output passed its limit: warns of each output past its own (logWatch), once,
  and gives the limits still armed.
- fast_outputs(inputs, read=None) -> (ok | warning, outputs) | error: takes
  the inputs and gives every output without stepping; `read` is the getReal's
  flat indices, a tuple of ints in order (None: every output). ok: the outputs
  are current until the next input write or call into the slave; warning: an
  input or parameter is invalid and the outputs that depend on it are held at
  the last valid inputs; the slave has warned if `read` holds one of them, as
  getReal warns only then, and again at every such read, so the runtime keeps
  them stale (and answers fmi2OK, as getReal does); error: a fault, logged.

Slave. The runtime constructs the slave itself (both FMI versions) and uses
that object; a slave without these methods or its `fast_flat` keeps plain
calls. Its `log_queue` list is made once (pythonfmu's `__init__`) and only
appended to: the runtime holds that list and drains it whenever it holds a
message (a slave that bound a new list would have its messages forwarded only
at its next plain call).

In C. setReal of inputs only: write known, mark outputs stale. Any other
setReal: fast_load if needed, forward to Python, fast_store. getReal: if the
outputs are stale, fast_outputs(inputs, read) first (even for a read of inputs
only: getReal evaluates the outputs whatever it is asked, and warns if an
output read is held); then known and outputs serve every reference the table
maps into them, anything else is forwarded (the slave reports it). doStep: the
generated step, else fast_do_step; outputs fresh when it is taken and
stored, stale otherwise.
"""

from collections.abc import Callable
from typing import Any

from ..framework.api import Stepped
from .references import References


class FastPath:
    """Mixed into `core.SlaveCore`, whose state and helpers these are."""

    _refs: References
    _STATUS: Any
    _model: Stepped
    _outputs: tuple | None
    _outputs_held: tuple
    _inputs_checked: bool
    _inputs_held: tuple
    _armed: Any
    _taken: Callable[[tuple, tuple], None]
    _current_outputs: Callable[[Any], tuple]
    _fault: Callable[[str, BaseException], None]
    _watch: Callable[[tuple], None]
    _watch_limits: Callable[[], tuple]
    do_step: Callable[[float, float], Any]
    # fast_state_size() was called: fast_store gives the model's step state.
    _state_exchange = False

    @classmethod
    def fast_layout(cls) -> dict:
        """The buffers' layout, for the runtime to size and index its arrays."""
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

    def fast_do_step(self, current_time, step_size, inputs=None):
        """A step the slave takes, in one call from the runtime: the host's
        inputs when written (fast_load), do_step, then what fast_store gives."""
        if inputs is not None:
            self.fast_load(inputs)
        return self.do_step(current_time, step_size), self.fast_store()

    def fast_store(self):
        """Every input and parameter and the last valid outputs, for the runtime's
        arrays: at instantiation and after every call into the slave; then the
        step state and the watches' limits."""
        try:
            stored = (self._refs.known_of(self._model), self._outputs_held)
            if self._state_exchange:
                stored += (tuple(self._model.step_state()), self._watch_limits())
            return self._STATUS.ok, *stored
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
        """The model where the generated steps left it, as `_taken` leaves it
        after a step in Python (so every later call sees the same)."""
        try:
            model: Any = self._model
            model.set_step_state(state)
            model.set_inputs(inputs)
            model.time = current_time
            self._taken(outputs, inputs)
            return self._STATUS.ok
        except Exception as error:
            self._fault("fast_sync", error)
            return self._STATUS.error

    def fast_watch(self):
        """A step taken in C passed an armed watch (the slave was synced): warn
        once, as after a step in Python; the limits left."""
        try:
            if self._armed:
                self._watch(self._outputs)
            return self._STATUS.ok, self._watch_limits()
        except Exception as error:
            self._fault("fast_watch", error)
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
