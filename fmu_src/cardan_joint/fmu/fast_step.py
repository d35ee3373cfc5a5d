"""The one-call step: what the native loader calls once per doStep instead of
setReal, doStep and getReal (issue 21).

The loader keeps each instance's values in two buffers of C doubles that it
shares with the slave (any writable buffer of doubles: a memoryview, an
array('d')), laid out by flat index as `References.layout` describes: the
*known* buffer holds the inputs then the parameters (flat indices 0 to
first_output - 1), the *output* buffer every output (flat index first_output + k
in slot k). The loader writes inputs into the known buffer in C; these methods
take them from there, step, and write every output at once, with the same
statuses, refusals, held outputs and messages as setReal, doStep and getReal.

Statuses are the FMI version's own (ok 0, warning 1, discard 2, error 3):
`fast_step` writes the outputs (and the inputs the step moved) only when it
returns ok (after a refused step they are read as after a write, see
`fast_outputs`); `fast_outputs` returns
warning when the outputs it wrote are held at the last valid inputs, which,
like getReal, it re-evaluates and reports at every read until the inputs are
valid, so the loader must not keep them.
"""

from collections.abc import Callable
from typing import Any

from .references import References


class FastStep:
    """Mixed into `core.SlaveCore`, whose state and helpers these are."""

    _refs: References
    table: Any
    _STATUS: Any
    _model: Any
    _outputs: tuple | None
    _inputs_checked: bool
    _inputs_held: tuple
    _step: Callable[[float, float], Any]
    _current_outputs: Callable[[], tuple]
    _fault: Callable[[str, BaseException], None]

    @classmethod
    def fast_layout(cls) -> dict:
        """The buffers' layout, for the loader to size and index its arrays."""
        return cls._refs.layout()

    def fast_load(self, known) -> None:
        """Take every input from the known buffer, as setReal of all inputs does
        (parameters are not read: they are set through setReal, see layout)."""
        model = self._model
        for name, value in zip(self.table.INPUTS, known):
            setattr(model, name, value)
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
            self.fast_load(known)
        except Exception as error:
            self._fault("fast_step", error)
            return self._STATUS.error
        status = self._step(current_time, step_size)
        if status != self._STATUS.ok:
            return status
        status = self._write_outputs(outputs, "fast_step")
        try:
            # A taken step moves the inputs that are polynomial over it (the speed,
            # the bend angle and rate): getReal of an input reads the moved value,
            # and the next step starts from it. The outputs' evaluation has just
            # read them (`_inputs_held`).
            self._refs.pack_inputs(known, 0, *self._inputs_held)
        except Exception as error:
            self._fault("fast_step", error)
            return self._STATUS.error
        return status

    def fast_outputs(self, known, outputs) -> int:
        """Inputs from `known`, then every output into `outputs` without stepping
        (a read after a write of an input: direct feedthrough)."""
        try:
            self.fast_load(known)
        except Exception as error:
            self._fault("fast_outputs", error)
            return self._STATUS.error
        return self._write_outputs(outputs, "fast_outputs")

    def _write_outputs(self, outputs, where: str) -> int:
        try:
            values = self._outputs or self._current_outputs()
            self._refs.pack_outputs(outputs, 0, *values)
            # Held outputs are not cached (`_current_outputs`): the next read
            # re-evaluates and warns again, as getReal does.
            return self._STATUS.ok if self._outputs is not None else self._STATUS.warning
        except Exception as error:
            self._fault(where, error)
            return self._STATUS.error
