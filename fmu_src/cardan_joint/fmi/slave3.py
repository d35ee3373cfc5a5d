"""The pythonfmu3 slave: the FMI 3.0 co-simulation face of `core.SlaveCore`.

No equation and no joint logic live here: this maps FMI 3 value references
(1-based positions, `references`: the independent variable `time`, then one per
FMI 3 variable: by default one scalar per row of the model's table, the FMI 2.0
variables; with `fmi3_arrays` (`--fmi3-arrays`) the table's `fmi3_variables()`,
vectors as Float64 arrays) onto the flat indices `core` works with. The FMU's
runtime (`cardan_joint.fmi.native`) constructs this slave and calls its methods
as pythonfmu3 0.3.4's C layer did: any Python exception becomes fmi3Fatal (so
every entry point catches everything), a getter's list must hold exactly
`nValues` values (so a getter always returns enough, NaN-padded when a value
reference is unknown: the runtime refuses any other length), `do_step` returns
a step result with any status, and every message goes to the runtime, which
hands it to the host's logger (or stderr when the host gave none). The runtime
checks value references and types first and serves Float64 variables only,
which are all this FMU has.
"""

import math

from pythonfmu3 import Float64, Fmi3Causality, Fmi3Slave, Fmi3Variability
from pythonfmu3.default_experiment import DefaultExperiment
from pythonfmu3.enums import Fmi3Initial, Fmi3Status
from pythonfmu3.fmi3slave import Fmi3StepResult
from pythonfmu3.variables import Dimension

from ..variable_schema import fmi3_groups
from .binding import ModelBinding
from .core import SlaveCore
from .model_description3 import complete
from .references import FIRST_VALUE_REFERENCE, log_categories

TIME_REFERENCE = FIRST_VALUE_REFERENCE  # `time` is the first variable


class ModelSlave3(ModelBinding, SlaveCore, Fmi3Slave):
    """The FMI 3 slave of every model: a model's script subclasses it and names
    its folder (`model_folder`), whose spec sets the table and the physics."""

    log_categories = log_categories("fmi3")
    _STATUS, _API, _STATE, _TYPE = Fmi3Status, "fmi3", "State", "Float64"
    # Vectors as Float64 arrays (written in by the build, `--fmi3-arrays`): hosts that
    # read a variable one value at a time (OMSimulator, Ecos) get nothing of an
    # array, so the default is the table's scalars, which every host reads.
    fmi3_arrays = False
    # The model's FMI 3 variables and, per value reference, the flat indices
    # it holds (`_FLAT`), its size, whether it can be set.
    GROUPS: tuple = ()
    fast_flat: tuple = ()
    _SIZE: tuple = ()
    _LONGEST = 1
    _SETTABLE: frozenset = frozenset()

    def __init_subclass__(cls, **kwargs):
        super().__init_subclass__(**kwargs)
        if cls.table is not None:
            cls._lay_out()

    @classmethod
    def _lay_out(cls):
        table = cls.table
        cls.GROUPS = groups = (
            table.fmi3_variables() if cls.fmi3_arrays else fmi3_groups(table.VARIABLES)
        )
        rows = [tuple(row.name for row in group.rows) for group in groups]
        cls._FLAT = cls._refs.reference_table([(), *rows])  # `time`: no flat index
        cls.fast_flat = cls._FLAT  # how the runtime's fast path maps value references
        cls._SIZE = tuple(len(flat) or 1 for flat in cls._FLAT)
        cls._LONGEST = max(cls._SIZE)
        cls._SETTABLE = frozenset(
            vr
            for vr, g in enumerate(groups, start=TIME_REFERENCE + 1)
            if g.causality in ("input", "parameter")
        )

    def __init__(self, **kwargs):
        super().__init__(**kwargs)
        # Fmi3SlaveBase.__init__ sets these on the instance: the class's would not show.
        cls = type(self)
        self.author, self.license, self.version = cls.author, cls.license, cls.version
        self.description = cls.description
        self.default_experiment = DefaultExperiment(**cls.experiment)
        self._init_model()
        self._publish(
            Float64(
                "time",
                causality=Fmi3Causality.independent,
                variability=Fmi3Variability.continuous,
                description="Simulation time",
            )
        )
        for group in self.GROUPS:
            self._register(group)

    def _register(self, group):
        initial = Fmi3Initial[group.initial] if group.initial else None
        variable = Float64(
            group.name,
            causality=Fmi3Causality[group.causality],
            description=group.description,
            variability=Fmi3Variability[group.variability],
            initial=initial,
            getter=lambda: None,
            setter=lambda value: None,
        )
        if len(group.rows) > 1:
            # Attached after construction: pythonfmu3 0.3.4 imports numpy for any
            # array variable only because its own array accessors need it; this
            # slave answers arrays itself (get_float64), on the standard library.
            variable._dimensions = [Dimension(start=str(len(group.rows)))]
        self._publish(variable)

    def to_xml(self, model_options=None):
        starts = {name: getattr(self._model, name) for name in self._refs.known}
        return complete(super().to_xml(model_options or {}), self.GROUPS, starts, self.table)

    # --- messages ------------------------------------------------------------

    def _report(self, message: str, status: Fmi3Status, category: str | None = None) -> None:
        # The runtime hands every message to the host's logger, or to stderr.
        self.log(message, status, category)

    # --- life cycle ----------------------------------------------------------

    def enter_initialization_mode(self):
        # pythonfmu3 0.3.4 does not pass fmi3EnterInitializationMode's start time on:
        # the clock starts at 0 and follows each fmi3DoStep's communication point.
        try:
            self._restart()
        except Exception as error:
            self._fault("enter_initialization_mode", error)

    def do_step(self, current_time, step_size):
        return Fmi3StepResult(status=self._step(current_time, step_size))

    # --- values --------------------------------------------------------------

    def get_float64(self, vrs):
        try:
            indices = self._flat_indices(vrs, "fmi3GetFloat64")
            if indices is None:
                return [math.nan] * (self._LONGEST * len(vrs))
            if TIME_REFERENCE in vrs:  # the one value reference with no flat index
                return [
                    value
                    for vr in vrs
                    for value in (
                        [self._model.time]
                        if vr == TIME_REFERENCE
                        else self._get_flat(list(self._FLAT[vr]))
                    )
                ]
            return self._get_flat(indices)
        except Exception as error:
            self._fault("fmi3GetFloat64", error)
            return [math.nan] * (self._LONGEST * len(vrs))

    def set_float64(self, vrs, values):
        try:
            indices = self._flat_indices(vrs, "fmi3SetFloat64")
            if indices is None:
                return
            sizes = [self._SIZE[vr] for vr in vrs]
            if len(values) != sum(sizes):
                self._report(
                    f"fmi3SetFloat64: {len(values)} values for {sum(sizes)} "
                    f"elements of value references {list(vrs)}: nothing set",
                    Fmi3Status.error,
                )
                return
            refused = [vr for vr in vrs if vr not in self._SETTABLE]
            if refused:
                names = ", ".join(self._fmi3_name(vr) for vr in refused)
                self._report(
                    f"fmi3SetFloat64 on {names} ignored: only inputs and parameters can be set",
                    Fmi3Status.error,
                )
                starts = [sum(sizes[:k]) for k in range(len(vrs))]
                kept = [k for k, vr in enumerate(vrs) if vr in self._SETTABLE]
                indices = [i for k in kept for i in self._FLAT[vrs[k]]]
                values = [v for k in kept for v in values[starts[k] : starts[k] + sizes[k]]]
            self._set_flat(indices, values, "fmi3SetFloat64")
        except Exception as error:
            self._fault("fmi3SetFloat64", error)

    def _fmi3_name(self, vr):
        return "time" if vr == TIME_REFERENCE else self.GROUPS[vr - TIME_REFERENCE - 1].name
