"""The one-call step: what the native loader calls once per doStep instead of
setReal, doStep and getReal (issue 21). This docstring is the protocol the
loader's C side follows.

Buffers. Per instance the loader owns two arrays of C doubles, sized and
indexed by `fast_layout()` (a class method: `References.layout`), and hands
them to these methods as writable buffers (PyMemoryView_FromMemory with
PyBUF_WRITE, created once per instance; bytes or doubles format alike: the
slave reads and writes native-order doubles through struct and keeps no
reference after a call):
- known[known_size]: flat index i in slot i: inputs (0 to inputs - 1), then
  parameters (inputs to known_size - 1);
- outputs[outputs]: flat index first_output + k in slot k.
Flat indices are the FMI 2 value references; an FMI 3 loader maps its value
references onto them as `slave3._FLAT` does (time and arrays aside).

Calls (statuses are the FMI version's own IntEnum: ok 0, warning 1, discard 2,
error 3; each call logs through the slave as any other call does, so the
loader forwards the log queue after it as after pythonfmu's calls):
- fast_store(known): writes every input and parameter into known. Call it
  after instantiation and after every call into the slave that can change
  them: a setReal forwarded to Python, exitInitializationMode, set or
  deserialized FMU state, reset.
- fast_load(known): takes the inputs (not the parameters) from known, as a
  setReal of every input would. Call it before every other call into the
  slave when an input was written since the last fast_* call (FMU state get,
  a forwarded setReal, terminate...), so the slave sees the host's inputs.
- fast_step(t, h, known, outputs): takes the inputs, steps; on ok it writes
  every output and the inputs the step moved (speed, bend angle and rate
  advance over a step: a later getReal of them, or the next step, reads the
  moved value). On discard (refused: the slave keeps its state and has logged
  variable, value, limit and time) or error nothing is written.
- fast_outputs(known, outputs): takes the inputs and writes every output
  without stepping. ok: the outputs are current until the next input write
  or call into the slave; warning: they are held at the last valid inputs and
  the slave has warned; getReal warns again at every read, so the loader keeps
  them stale (and answers fmi2OK, as getReal does); error: a fault, logged.

Claim. The FMI 2.0 runtime constructs the slave itself and uses it. pythonfmu3
(FMI 3.0) does not hand its Python object out: each slave registers itself at
construction, per thread (`_fast_register`), and the FMI 3.0 loader calls the
class's `fast_claim(instance_name)` right after instantiate and reset on the
same thread. A slave without these methods keeps plain calls.

In C. setReal of inputs only: write known, mark outputs stale. Any other
setReal: fast_load if needed, forward to Python, fast_store. getReal: if the
outputs are stale, fast_outputs first (even for a read of inputs only: getReal
evaluates the outputs, and warns, whatever it is asked); then known and
outputs serve every index below first_output + outputs, anything else is
forwarded (the slave reports it). doStep: fast_step; outputs fresh on ok,
stale otherwise.
"""

import threading
import weakref
from collections.abc import Callable
from typing import Any

from ..framework.api import Stepped
from .references import References

# The slave each thread constructed last: pythonfmu keeps its Python object to
# itself, so the loader claims it (`fast_claim`) right after pythonfmu's
# instantiate or reset returned on the same thread. Keyed by thread, so
# instances made at once on several threads never mix; weak, so a slave made
# outside the loader is not kept alive.
_constructed: dict = {}


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
    _current_outputs: Callable[[], tuple]
    _fault: Callable[[str, BaseException], None]

    def _fast_register(self) -> None:
        _constructed[threading.get_ident()] = weakref.ref(self)

    @staticmethod
    def fast_claim(instance_name: str):
        """The slave this thread constructed last if it is `instance_name`'s, else None."""
        entry = _constructed.pop(threading.get_ident(), None)
        slave = entry() if entry else None
        return slave if slave is not None and slave.instance_name == instance_name else None

    @classmethod
    def fast_layout(cls) -> dict:
        """The buffers' layout, for the loader to size and index its arrays."""
        return cls._refs.layout()

    def fast_load(self, known) -> int:
        """Take every input from the known buffer, as setReal of all inputs does
        (parameters are not read: they are set through setReal, see layout)."""
        try:
            self._take_inputs(known)
            return self._STATUS.ok
        except Exception as error:
            self._fault("fast_load", error)
            return self._STATUS.error

    def _take_inputs(self, known) -> None:
        self._model.set_inputs(self._refs.unpack_inputs(known))
        self._outputs = None
        self._inputs_checked = False

    def fast_store(self, known) -> int:
        """Write the instance's inputs and parameters into the known buffer: at
        instantiation and after anything that changes them in Python (a
        parameter set, an FMU state set, a reset)."""
        try:
            self._refs.pack_known(known, 0, *self._refs.known_of(self._model))
            return self._STATUS.ok
        except Exception as error:
            self._fault("fast_store", error)
            return self._STATUS.error

    def fast_step(self, current_time, step_size, known, outputs) -> int:
        """Inputs from `known`, one step, every output into `outputs` when the step
        is taken (status ok); otherwise the status of the refusal or fault."""
        try:
            model, refs = self._model, self._refs
            # The model's step takes the inputs, steps and evaluates its outputs once.
            result = model.run(current_time, step_size, refs.unpack_inputs(known))
            if result.__class__ is not tuple:
                self._outputs = None
                self._inputs_checked = False
                return self._refused(result, current_time, step_size)
            self._outputs = self._outputs_held = result
            self._inputs_checked = True
            # A taken step moves the inputs that are polynomial over it (the speed,
            # the bend angle and rate): getReal of an input reads the moved value,
            # and the next step starts from it.
            inputs = self._inputs_held = model.inputs()
            refs.pack_outputs(outputs, 0, *result)
            refs.pack_inputs(known, 0, *inputs)
            return self._STATUS.ok
        except Exception as error:
            self._fault("fast_step", error)
            return self._STATUS.error

    def fast_outputs(self, known, outputs) -> int:
        """Inputs from `known`, then every output into `outputs` without stepping
        (a read after a write of an input: direct feedthrough)."""
        try:
            self._take_inputs(known)
            self._refs.pack_outputs(outputs, 0, *self._current_outputs())
            # Held outputs are not cached (`_current_outputs`): the next read
            # re-evaluates and warns again, as getReal does.
            return self._STATUS.ok if self._outputs is not None else self._STATUS.warning
        except Exception as error:
            self._fault("fast_outputs", error)
            return self._STATUS.error
