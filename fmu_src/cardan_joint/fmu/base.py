"""FMI plumbing every pythonfmu slave of this project shares.

pythonfmu 0.7.0 turns any Python exception reaching its C layer into fmi2Fatal
and forwards log messages only with debug logging on. So: problems are reported
through the FMU logger and also written to stderr (once per distinct message);
the FMUs have Real variables only, and the typed accessors for other types
refuse politely instead of raising; FMU states serialize to JSON and a bad
blob becomes a marked state that fmi2SetFMUstate explains. The model
description is completed from the slave's variable `table`.
"""

import json
import sys

from pythonfmu import Fmi2Causality, Fmi2Slave, Fmi2Variability, Real
from pythonfmu.enums import Fmi2Initial, Fmi2Status

from .model_description import complete


class TableSlave(Fmi2Slave):
    # The model's variable table (VARIABLES, BY_NAME, INPUTS, PARAMETERS, OUTPUTS, UNITS).
    table = None

    def __init__(self, **kwargs):
        super().__init__(**kwargs)
        self._last_message = None

    def to_xml(self, model_options=None):
        options = {"canGetAndSetFMUstate": True, "canSerializeFMUstate": True,
                   **(model_options or {})}
        return complete(super().to_xml(options), self.table)

    def _register(self, variable):
        """Register `variable` under the next value reference, read and written through
        get_real/set_real (so one code path serves FMI calls and Python access)."""
        causality = Fmi2Causality[variable.causality]
        initial = Fmi2Initial[variable.initial] if variable.initial else None
        reference = len(self.vars)
        self.register_variable(Real(
            variable.name, causality=causality, description=variable.description,
            variability=Fmi2Variability[variable.variability], initial=initial,
            getter=lambda: self.get_real([reference])[0],
            setter=lambda value: self.set_real([reference], [value])))

    # --- messages ------------------------------------------------------------

    def _report(self, message: str, status: Fmi2Status) -> None:
        self.log(message, status)
        if message != self._last_message:
            self._last_message = message
            # pythonfmu forwards log messages only with debug logging on, so a user
            # of plain fmpy.simulate_fmu would never learn why the run stopped.
            # A host without a usable stderr must not turn this into fmi2Fatal.
            try:
                sys.stderr.write(f"[{self.modelName} {self.instance_name}] "
                                 f"{status.name.upper()}: {message}\n")
                sys.stderr.flush()
            except Exception:
                pass

    def _fault(self, where: str, error: BaseException) -> None:
        try:
            self._report(f"internal error in {where}: {type(error).__name__}: {error}",
                         Fmi2Status.error)
        except Exception:
            pass

    # The FMUs have Real variables only; pythonfmu's typed accessors would raise
    # (fmi2Fatal) on any other call, so these refuse politely instead.
    def _no_such_variables(self, kind, vrs):
        self._report(f"the FMU has no {kind} variables (value references {list(vrs)})",
                     Fmi2Status.error)

    def get_integer(self, vrs):
        self._no_such_variables("Integer", vrs)
        return [0] * len(vrs)

    def get_boolean(self, vrs):
        self._no_such_variables("Boolean", vrs)
        return [False] * len(vrs)

    def get_string(self, vrs):
        self._no_such_variables("String", vrs)
        return [""] * len(vrs)

    def set_integer(self, vrs, values):
        self._no_such_variables("Integer", vrs)

    def set_boolean(self, vrs, values):
        self._no_such_variables("Boolean", vrs)

    def set_string(self, vrs, values):
        self._no_such_variables("String", vrs)

    # --- FMU state serialization --------------------------------------------

    @staticmethod
    def _fmu_state_to_bytes(state):
        try:
            return json.dumps(state).encode("utf-8")
        except Exception as error:
            return json.dumps({"invalid_state": f"serialization failed: {error}"}).encode()

    @staticmethod
    def _fmu_state_from_bytes(data):
        # Returning a marked state instead of raising: fmi2SetFMUstate then says why.
        try:
            state = json.loads(data.decode("utf-8"))
            if not isinstance(state, dict):
                raise ValueError("not a serialized state of this FMU")
            return state
        except Exception as error:
            return {"invalid_state": f"fmi2DeSerializeFMUstate got no valid state: {error}"}
