"""The pythonfmu (FMI 2.0) slave: the FMI 2 face of `core.SlaveCore`.

No equation and no model logic live here (that is `core`, for every model and
both FMI versions): value reference r is the r-th variable (1-based, see
`references`), flat index r - 1 of the core. What lives here is FMI 2 plumbing
that pythonfmu 0.7.0 gets wrong for a robust component: any Python exception
reaching its C layer becomes fmi2Fatal, so every method it calls catches
everything; a refused step returns False (the runtime answers fmi2Error, the
status its message is logged with); the typed accessors of other types refuse
politely; and every problem is logged (the FMU's native loader makes sure it reaches the host, see
`cardan_joint.fmi.native`).
"""

import math

from pythonfmu import Fmi2Causality, Fmi2Slave, Fmi2Variability, Real
from pythonfmu.default_experiment import DefaultExperiment
from pythonfmu.enums import Fmi2Initial, Fmi2Status

from .binding import ModelBinding
from .core import SlaveCore
from .model_description import complete
from .references import log_categories


class ModelSlave(ModelBinding, SlaveCore, Fmi2Slave):
    """The FMI 2 slave of every model: a model's script subclasses it and names
    its folder (`model_folder`), whose spec sets the table and the physics."""

    default_experiment = DefaultExperiment(**SlaveCore.experiment)
    log_categories = log_categories("fmi2")
    _STATUS, _API, _STATE, _TYPE = Fmi2Status, "fmi2", "state", "Real"

    def __init_subclass__(cls, **kwargs):
        super().__init_subclass__(**kwargs)
        if cls.table is not None:
            # One variable per flat index, in flat order.
            cls._FLAT = cls._refs.reference_table((name,) for name in cls._refs.names)
            cls.fast_flat = cls._FLAT  # how the native loader maps value references

    def __init__(self, **kwargs):
        super().__init__(**kwargs)
        self._init_model()
        for name in self._refs.names:
            self._register(self.table.BY_NAME[name])

    def _register(self, variable):
        causality = Fmi2Causality[variable.causality]
        initial = Fmi2Initial[variable.initial] if variable.initial else None
        real = Real(
            variable.name,
            causality=causality,
            description=variable.description,
            variability=Fmi2Variability[variable.variability],
            initial=initial,
            getter=lambda: self.get_real([real.value_reference])[0],
            setter=lambda value: self.set_real([real.value_reference], [value]),
        )
        self._publish(real)

    def to_xml(self, model_options=None):
        options = {
            "canGetAndSetFMUstate": True,
            "canSerializeFMUstate": True,
            **(model_options or {}),
        }
        starts = {name: getattr(self._model, name) for name in self._refs.known}
        return complete(super().to_xml(options), self.table, starts)

    def _report(self, message: str, status: Fmi2Status, category: str | None = None) -> None:
        # No stderr here: the FMU's native loader hands every message to the host's
        # logger (warnings and refusals even with debug logging off), or to stderr
        # when the host gave no logger or $CARDAN_JOINT_FMU_STDERR asks for it.
        self.log(message, status, category)

    # --- life cycle ----------------------------------------------------------

    def setup_experiment(self, start_time, stop_time=None, tolerance=None):
        try:
            self._start_time = float(start_time)
            self._restart()
        except Exception as error:
            self._fault("setup_experiment", error)

    def do_step(self, current_time, step_size):
        return self._step(current_time, step_size) == Fmi2Status.ok

    # --- values --------------------------------------------------------------

    def get_real(self, vrs):
        try:
            indices = self._flat_indices(vrs, "get_real")
            return [math.nan] * len(vrs) if indices is None else self._get_flat(indices)
        except Exception as error:
            self._fault("get_real", error)
            return [math.nan] * len(vrs)

    def set_real(self, vrs, values):
        indices = self._flat_indices(vrs, "set_real")
        if indices is not None:
            self._set_flat(indices, values, "set_real")

    # The FMU has Real variables only; pythonfmu's typed accessors would raise
    # (fmi2Fatal) on any other call, so these refuse politely instead.
    def _no_such_variables(self, kind, vrs):
        self._report(
            f"the FMU has no {kind} variables (value references {list(vrs)})", Fmi2Status.error
        )

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
