"""Design sweeps of the UniversalJoint FMU, serially or on Dask.

A sweep crosses bend angles, input speeds and crosspiece inertia distributions
(the paper's T1..T4 of a total I0 = (I1 + I2 + I3) / 2) and co-simulates each
case at constant inputs over whole input revolutions, sampled at a fixed angle
step so that fast and slow shafts are resolved alike. Each row of the tidy
result table holds one case's peaks, or its status "failed" and the FMU's
message: a refused run is reported, never dropped.

    spec.py       the grid of cases and their shared settings
    case.py       one case: co-simulation and peaks (runs on a worker)
    execution.py  serial and Dask runs, progress, the cluster
    store.py      one file per finished case (resume), the tidy table
    heatmap.py    the figure
    timing.py     serial against Dask (--compare)
    command.py    the command line
"""

from ..results import write_table
from .case import run_case, run_task
from .command import add_arguments, main, spec_from_arguments
from .execution import connect, local_cluster, run_dask, run_serial, warm_up
from .heatmap import cell_edges, plot_heatmaps
from .spec import ACCELERATION_LIMIT, FAILED, INERTIA_DISTRIBUTIONS, OK, PEAKS, Case, SweepSpec
from .store import CaseStore, SettingsMismatch, to_table
from .timing import compare

__all__ = [
    "ACCELERATION_LIMIT",
    "FAILED",
    "INERTIA_DISTRIBUTIONS",
    "OK",
    "PEAKS",
    "Case",
    "CaseStore",
    "SettingsMismatch",
    "SweepSpec",
    "add_arguments",
    "cell_edges",
    "compare",
    "connect",
    "local_cluster",
    "main",
    "plot_heatmaps",
    "run_case",
    "run_dask",
    "run_serial",
    "run_task",
    "spec_from_arguments",
    "to_table",
    "warm_up",
    "write_table",
]
