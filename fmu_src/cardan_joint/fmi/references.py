"""How a slave addresses a variable table: flat indices (inputs, then
parameters, then outputs: the FMI 2 value references) and the log categories
every FMU of this project declares."""

import math
from operator import attrgetter

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
        # The one-call step's known array (`fast_store`), in slot order.
        self.known_of = _values_of(self.known)

    def layout(self) -> dict:
        """The one-call step's buffers (fmi/fast_step.py), by flat index.

        known: `known_size` doubles, flat index i in slot i: the inputs (slots
        0 to inputs - 1), then the parameters (slots inputs to known_size - 1).
        outputs: `outputs` doubles, flat index first_output + k in slot k.
        names: every variable, by flat index (the FMI 2 value reference).
        """
        return {
            "inputs": len(self.inputs),
            "parameters": self.first_output - len(self.inputs),
            "known_size": self.first_output,
            "first_output": self.first_output,
            "outputs": len(self.names) - self.first_output,
            "names": list(self.names),
        }
