"""The pythonfmu slave: maps FMI variables onto `physics.CardanJoint`.

No equation lives here, and what the FMI 3 slave shares (the output cache,
held outputs, refused steps, fixed parameters, the FMU state) lives in
`joint_core`. What lives here is FMI 2 plumbing that pythonfmu 0.7.0 gets
wrong for a robust component: any Python exception reaching its C layer
becomes fmi2Fatal, so every method it calls catches everything; a refused step
returns False (fmi2Discard) with the joint untouched; and every problem is
also written to stderr, because pythonfmu drops log messages unless debug
logging is on.
"""

import math

from pythonfmu import Fmi2Causality, Fmi2Slave, Fmi2Variability, Real
from pythonfmu.default_experiment import DefaultExperiment
from pythonfmu.enums import Fmi2Initial, Fmi2Status

from .. import variables as table
from . import joint_core as core
from .joint_core import JointCore
from .model_description import complete

_NAMES = core.NAMES


class CardanJointSlave(JointCore, Fmi2Slave):
    author = core.AUTHOR
    license = core.LICENSE
    version = core.VERSION
    description = core.DESCRIPTION
    default_experiment = DefaultExperiment(start_time=core.START_TIME, stop_time=core.STOP_TIME,
                                           step_size=core.STEP_SIZE)
    log_categories = core.log_categories("fmi2")
    _STATUS, _API, _STATE = Fmi2Status, "fmi2", "state"

    def __init__(self, **kwargs):
        super().__init__(**kwargs)
        self._init_joint()
        for name in _NAMES:
            self._register(table.BY_NAME[name])

    def _register(self, variable):
        causality = Fmi2Causality[variable.causality]
        initial = Fmi2Initial[variable.initial] if variable.initial else None
        reference = len(self.vars)
        self.register_variable(Real(
            variable.name, causality=causality, description=variable.description,
            variability=Fmi2Variability[variable.variability], initial=initial,
            getter=lambda: self.get_real([reference])[0],
            setter=lambda value: self.set_real([reference], [value])))

    def to_xml(self, model_options=None):
        options = {"canGetAndSetFMUstate": True, "canSerializeFMUstate": True,
                   **(model_options or {})}
        return complete(super().to_xml(options))

    # --- messages ------------------------------------------------------------

    def _report(self, message: str, status: Fmi2Status) -> None:
        self.log(message, status)
        # pythonfmu forwards log messages only with debug logging on, so a user
        # of plain fmpy.simulate_fmu would never learn why the run stopped.
        self._echo_to_stderr(message, status)

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
            return self._get_flat(vrs)
        except Exception as error:
            bad = [vr for vr in vrs if not 0 <= vr < len(_NAMES)]
            if bad:
                self._report(f"get_real: no Real variable has value reference {bad[0]}",
                             Fmi2Status.error)
            else:
                self._fault("get_real", error)
            return [math.nan] * len(vrs)

    def set_real(self, vrs, values):
        self._set_flat(vrs, values, "set_real")

    # The FMU has Real variables only; pythonfmu's typed accessors would raise
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
