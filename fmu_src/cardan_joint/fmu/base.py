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
import math
import sys

from pythonfmu import Fmi2Causality, Fmi2Slave, Fmi2Variability, Real
from pythonfmu.default_experiment import DefaultExperiment
from pythonfmu.enums import Fmi2Initial, Fmi2Status

from .. import __version__
from .model_description import complete


class TableSlave(Fmi2Slave):
    author = "Cardan joint FMU team"
    license = "MIT"
    version = __version__
    default_experiment = DefaultExperiment(start_time=0.0, stop_time=2.0, step_size=1e-3)
    log_categories = {
        "logStatusWarning": "Warnings: outputs held at the last valid inputs.",
        "logStatusDiscard": "Refused steps: the variable, its value, the limit and the time.",
        "logStatusError": "Errors: invalid parameters, calls FMI does not allow, internal faults.",
        "logStatusFatal": "Not used: the FMU never ends in fmi2Fatal on its own.",
        "logAll": "All messages.",
    }
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

    # --- Real values -----------------------------------------------------------

    def _get_real_failed(self, vrs, error, n_variables):
        """get_real's answer when it raised: NaNs, and why (a bad reference or a fault)."""
        bad = [vr for vr in vrs if not 0 <= vr < n_variables]
        if bad:
            self._report(f"get_real: no Real variable has value reference {bad[0]}",
                         Fmi2Status.error)
        else:
            self._fault("get_real", error)
        return [math.nan] * len(vrs)

    def _write_permitted(self, vr, name, value, n_inputs, n_settable) -> bool:
        """Whether set_real may write value reference `vr` now: inputs always,
        parameters until initialization ends; if not, says why."""
        if not 0 <= vr < n_settable:
            self._report(f"set_real on {name} ignored: only inputs and parameters can be set",
                         Fmi2Status.error)
            return False
        if vr >= n_inputs and self._initialized:
            self._report(f"parameter {name} = {value!r} ignored: fixed parameters cannot "
                         f"change after initialization", Fmi2Status.error)
            return False
        return True

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

    # --- FMU state ------------------------------------------------------------
    # A subclass saves its own parts (`_state_parts`), restores them all or nothing
    # (`_restore_parts`, raising on anything malformed) and drops caches afterwards
    # (`_state_restored`); `_state_owner` names what keeps its state on a refusal.
    _state_owner = "FMU"

    def _state_restored(self):
        pass

    def _get_fmu_state(self):
        try:
            return {**self._state_parts(), "start_time": self._start_time,
                    "initialized": self._initialized}
        except Exception as error:
            self._fault("fmi2GetFMUstate", error)
            return {"invalid_state": f"fmi2GetFMUstate failed: {error}"}

    def _set_fmu_state(self, state):
        try:
            if "invalid_state" in state:
                raise ValueError(state["invalid_state"])
            start_time, initialized = float(state["start_time"]), bool(state["initialized"])
            self._restore_parts(state)
            self._start_time, self._initialized = start_time, initialized
        except Exception as error:
            self._report(f"fmi2SetFMUstate ignored, the {self._state_owner} keeps its state: "
                         f"{type(error).__name__}: {error}", Fmi2Status.error)
        finally:
            self._state_restored()

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
