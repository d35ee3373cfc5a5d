"""Benchmark floor: the UniversalJoint's Real variables and nothing else.

A pythonfmu script that `benchmarks.floor.build_floor_fmu` builds into an FMU
with as many Real variables as the joint, with the same names, causality,
variability, initial and start, and a `do_step` that does nothing: what it
costs per step is pythonfmu's and the master's share.

The build ships this file under a module name unique to its content and kind
(two FMUs whose scripts share a module name would run the same code in one
process) with `floor.json` beside it: the variables, and the value access,
"plain" (pythonfmu's own get_real/set_real, one attribute getter and setter
per variable) or "bare" (list indexing, the least Python a slave can run per
call).
"""

import ctypes
import json
from pathlib import Path

from pythonfmu import Fmi2Causality, Fmi2Slave, Fmi2Variability, Real
from pythonfmu.enums import Fmi2Initial

# pythonfmu 0.7.0's loader releases one reference too many to this module's
# namespace at every fmi2Instantiate (see fmu_src/cardan_joint/fmi/script2.py).
ctypes.pythonapi.Py_IncRef(ctypes.py_object(globals()))

CONFIG = json.loads(Path(__file__).with_name("floor.json").read_text())


class Floor(Fmi2Slave):
    def __init__(self, **kwargs):
        super().__init__(**kwargs)
        for name, causality, variability, initial, start in CONFIG["variables"]:
            setattr(self, name, 0.0 if start is None else start)
            self.register_variable(
                Real(
                    name,
                    causality=Fmi2Causality[causality],
                    variability=Fmi2Variability[variability],
                    initial=Fmi2Initial[initial] if initial else None,
                )
            )
        self._values = [getattr(self, name) for name, *_ in CONFIG["variables"]]

    def do_step(self, current_time, step_size):
        return True


def _indexed_get_real(self, vrs):
    values = self._values
    return [values[vr] for vr in vrs]


def _indexed_set_real(self, vrs, values):
    stored = self._values
    for vr, value in zip(vrs, values):
        stored[vr] = value


if CONFIG["value_access"] == "bare":
    # On the class, as an override would be: this module is this FMU's alone.
    Floor.get_real = _indexed_get_real
    Floor.set_real = _indexed_set_real
