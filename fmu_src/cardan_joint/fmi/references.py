"""How a slave addresses a variable table: flat indices (inputs, then
parameters, then outputs), the value references that map onto them, and the log
categories every FMU of this project declares.

Value reference r is the variable at 1-based position r in the model
description's <ModelVariables> (FMI 3.0: `time` first), in both FMI versions.
The standard reads <Dependencies> (FMI 3.0) and the `dependencies` of FMI 2.0's
<Unknown> as value references and positions respectively; OMSimulator reads
FMI 3.0's as positions too. Numbered so, every reading names the same variables.
"""

import math
from collections.abc import Callable
from operator import attrgetter
from typing import Any

FIRST_VALUE_REFERENCE = 1

# A watched output past its rating or margin (fmi/watching.py).
WATCH_CATEGORY = "logWatch"


def log_categories(api: str) -> dict:
    return {
        "logStatusWarning": "Warnings: outputs held at the last valid inputs.",
        WATCH_CATEGORY: "Warnings, once each: an output past its rating or margin "
        "(torque, life, critical speed, twist); the run goes on.",
        "logStatusDiscard": f"Not used: a refused step ends in {api}Error (logStatusError).",
        "logStatusError": "Errors: refused steps (the variable, its value, the limit and the "
        "time), invalid parameters, calls FMI does not allow, internal faults.",
        "logStatusFatal": f"Not used: the FMU never ends in {api}Fatal on its own.",
        "logAll": "All messages.",
    }


def _values_of(names):
    """A getter of the tuple of `names`' values (attrgetter gives one name's bare value)."""
    getter = attrgetter(*names)
    return getter if len(names) > 1 else lambda model: (getter(model),)


class References:
    """Flat indices of one variable table: inputs, then parameters, then outputs."""

    def __init__(self, table, live_outputs):
        self.known = table.INPUTS + table.PARAMETERS
        self.names = self.known + table.OUTPUTS
        self.first_output = len(self.known)
        assert tuple(v.name for v in table.VARIABLES) == self.names, (
            "flat indices assume inputs, then parameters, then outputs"
        )
        assert table.OUTPUTS[: len(live_outputs)] == live_outputs, (
            "the outputs that follow the state while inputs are invalid come first"
        )
        self.inputs = range(len(table.INPUTS))
        self.nan_outputs = (math.nan,) * len(table.OUTPUTS)
        self.output_dependencies = tuple(
            frozenset(table.BY_NAME[n].depends_on) for n in table.OUTPUTS
        )
        # What FMPy and most masters pass every step: all inputs, all outputs, in order.
        self.all_inputs = list(self.inputs)
        self.all_outputs = list(range(self.first_output, len(self.names)))
        # The fast path's known array (`fast_store`), in slot order.
        self.known_of = _values_of(self.known)

    def reference_table(self, variables) -> tuple:
        """Per value reference, the flat indices its variable holds. `variables`: the
        model description's variables in document order, each as the names of its
        rows (an FMI 3.0 array has several, `time` none); value reference r is the
        r-th of them, so the references below FIRST_VALUE_REFERENCE hold none."""
        flat = {name: i for i, name in enumerate(self.names)}
        unused = ((),) * FIRST_VALUE_REFERENCE
        return unused + tuple(tuple(flat[name] for name in rows) for rows in variables)

    def layout(self) -> dict:
        """The fast path's buffers (fmi/fast_path.py), by flat index.

        known: `known_size` doubles, flat index i in slot i: the inputs (slots
        0 to inputs - 1), then the parameters (slots inputs to known_size - 1).
        outputs: `outputs` doubles, flat index first_output + k in slot k.
        names: every variable, by flat index.
        """
        return {
            "inputs": len(self.inputs),
            "parameters": self.first_output - len(self.inputs),
            "known_size": self.first_output,
            "first_output": self.first_output,
            "outputs": len(self.names) - self.first_output,
            "names": list(self.names),
        }


class ValueReferences:
    """Mixed into every slave: its variables registered under their value
    references and those references mapped onto flat indices."""

    # Per value reference, the flat indices it holds (`References.reference_table`).
    _FLAT: tuple = ()
    vars: dict  # the pythonfmu base's registered variables
    # Set by each FMI version's slave: its real type's name, for messages.
    _TYPE: str
    # The slave's (`core.SlaveCore`).
    _STATUS: Any
    _report: Callable[[str, Any], None]
    _fault: Callable[[str, BaseException], None]

    def _publish(self, variable) -> None:
        """Register a pythonfmu variable under value reference = its 1-based position
        in the model description (`references`). Not `register_variable`, which
        numbers from 0 once and for all; the slave answers every get and set itself."""
        reference = len(self.vars) + FIRST_VALUE_REFERENCE
        self.vars[reference] = variable
        variable.value_reference = reference

    def _flat_indices(self, vrs, caller):
        """The flat indices of value references `vrs`, or None after reporting the
        first that names no variable (as an error of `caller`)."""
        try:
            table, indices = self._FLAT, []
            for vr in vrs:
                if not FIRST_VALUE_REFERENCE <= vr < len(table):
                    self._report(
                        f"{caller}: no {self._TYPE} variable has value reference {vr}",
                        self._STATUS.error,
                    )
                    return None
                indices.extend(table[vr])
            return indices
        except Exception as error:
            self._fault(caller, error)
            return None
