"""Run the FMU in OSP libcosim through its Python wrapper ``libcosimpy``.

``pip install -e '.[cosim]'`` installs it (checked with 0.0.6, manylinux_2_28 wheel). The wheel
bundles ``libcosimc.so`` with libcosim, FMI Library and Boost linked in, so no
system package is needed. It is imported lazily: this module imports without it.

Things worth knowing:

* Time is an ``int64`` count of **nanoseconds** everywhere in libcosim (step size,
  ``simulate_until``, ``status().current_time``, observer time points).
  ``step_size`` and ``stop_time`` are rounded to whole nanoseconds here.
* A pythonfmu FMU embeds no interpreter; its shared library uses the interpreter
  of the process that loads it. Running libcosim inside this Python process is
  therefore all it needs. libcosim calls the FMU on a worker thread; that works
  because ctypes releases the GIL and pythonfmu takes it with ``PyGILState``.
* The first ``step`` call initialises the FMU (setup, enter/exit initialisation
  mode) and then does the first ``doStep``. Initial values
  (``cosim_execution_set_real_initial_value``) are applied during that
  initialisation. Unconnected inputs keep the last value set, so constant inputs
  need no manipulator.
* The time-series observer records **step 0 at t = 0 after initialisation**
  (outputs computed from the start values, before any ``doStep``), then one
  sample after each step. So ``n`` steps give ``n + 1`` samples, like FMPy.
* ``CosimObserver.create_time_series()`` without a size, documented upstream as
  "unbuffered", keeps only the **last 10000 samples** per variable (a 10 s run
  at 1 ms silently lost t = 0). The buffer is sized to the run here.
* ``CosimObserver.time_series_real_samples`` in libcosimpy 0.0.6 drops samples:
  it trims its buffer by counting step numbers equal to 0, which also counts the
  real step-0 sample. The C function is therefore called directly here.
* libcosim logs at ``debug`` level to stderr by default (FMI Library chatter);
  this sets the process-wide level to ``warning``.
* An SSP archive loads with ``CosimExecution.from_ssp_file`` (fixed step): its
  connections are then transferred after every step from the outputs the FMUs
  report after that step (explicit, Jacobi-type coupling); at initialisation the
  initial outputs are passed through before the first step.
* libcosim unpacks the FMU under ``/tmp/libcosim_<uuid>`` and removes it when
  the execution is destroyed.
"""

from __future__ import annotations

import ctypes
from collections.abc import Mapping
from pathlib import Path
from typing import Any

import numpy as np

from ..extras import require

_NANOSECONDS_PER_SECOND = 1_000_000_000


def _ns(seconds: float) -> int:
    return int(round(seconds * _NANOSECONDS_PER_SECOND))


def _check(ok, what):
    from libcosimpy._internal import get_last_error_message

    if not ok:
        raise RuntimeError(f"libcosim: {what} failed: {get_last_error_message()}")


def _steps(stop_time, step_size):
    step_ns, stop_ns = _ns(step_size), _ns(stop_time)
    n_steps = round(stop_ns / step_ns) if step_ns > 0 else 0
    if step_ns <= 0 or n_steps < 1 or n_steps * step_ns != stop_ns:
        raise ValueError(
            f"stop_time {stop_time} is not a positive whole number of steps {step_size}"
        )
    return step_ns, n_steps


def _real_references(execution, index, where):
    from libcosimpy.CosimEnums import CosimVariableType

    refs = {
        v.name.decode(): v.reference
        for v in execution.slave_variables(index)
        if CosimVariableType(v.type) is CosimVariableType.REAL
    }

    def ref(name):
        if name not in refs:
            raise KeyError(f"{name!r} is not a Real variable of {where}")
        return refs[name]

    return ref


def _observe_and_run(
    execution: Any, observed: Mapping[str, tuple[int, int]], n_steps: int, step_ns: int
) -> dict[str, np.ndarray]:
    """Step `execution` `n_steps` times recording `observed` = {key: (slave index,
    value reference)}; return {"time": t, key: values} with n_steps + 1 samples."""
    from libcosimpy._internal import libcosimc
    from libcosimpy.CosimEnums import CosimVariableType
    from libcosimpy.CosimObserver import CosimObserver

    n = n_steps + 1
    observer = CosimObserver.create_time_series(n)  # the default one keeps only the last 10000
    _check(execution.add_observer(observer), "adding observer")
    for key, (index, reference) in observed.items():
        _check(
            observer.start_time_series(index, reference, CosimVariableType.REAL), f"observing {key}"
        )

    _check(execution.step(n_steps), "stepping")

    get_samples = libcosimc().cosim_observer_slave_get_real_samples
    get_samples.restype = ctypes.c_int64
    get_samples.argtypes = [
        ctypes.c_void_p,
        ctypes.c_int,
        ctypes.c_uint32,
        ctypes.c_int64,
        ctypes.c_size_t,
        ctypes.c_void_p,
        ctypes.c_void_p,
        ctypes.c_void_p,
    ]
    result: dict[str, np.ndarray] = {}
    for key, (index, reference) in observed.items():
        values, steps, times = np.empty(n), np.empty(n, np.int64), np.empty(n, np.int64)
        got = get_samples(
            ctypes.cast(observer.ptr(), ctypes.c_void_p),
            index,
            reference,
            0,
            n,
            values.ctypes.data,
            steps.ctypes.data,
            times.ctypes.data,
        )
        _check(
            got == n and np.array_equal(steps, np.arange(n)),
            f"reading {key} ({got} of {n} samples)",
        )
        result.setdefault("time", times / _NANOSECONDS_PER_SECOND)
        result[key] = values
    if "time" not in result:
        result["time"] = np.arange(n) * step_ns / _NANOSECONDS_PER_SECOND
    del observer
    return result


def run_libcosim(
    fmu_path,
    stop_time,
    step_size,
    inputs: dict[str, float],
    outputs: list[str],
    start_values: dict[str, float] | None = None,
) -> dict[str, np.ndarray]:
    """Simulate one FMU alone in libcosim with constant real ``inputs``.

    ``inputs`` and ``start_values`` (real parameters or inputs) are set as initial
    values and held. The fixed step is ``step_size``; ``stop_time`` must be a whole
    number of steps. Returns ``{"time": t, name: values, ...}`` with
    ``round(stop_time / step_size) + 1`` samples starting at t = 0.
    """
    require("libcosimpy", "cosim", "running in libcosim")
    from libcosimpy.CosimExecution import CosimExecution
    from libcosimpy.CosimLogging import CosimLogLevel, log_output_level
    from libcosimpy.CosimSlave import CosimLocalSlave

    step_ns, n_steps = _steps(stop_time, step_size)
    log_output_level(CosimLogLevel.WARNING)
    execution = CosimExecution.from_step_size(step_ns)
    slave = CosimLocalSlave(fmu_path=str(Path(fmu_path).resolve()), instance_name="fmu")
    _check(slave.ptr(), f"loading {fmu_path}")  # adding a NULL slave segfaults
    index = execution.add_local_slave(slave)
    _check(index >= 0, f"adding {fmu_path}")
    ref = _real_references(execution, index, fmu_path)
    for name, value in {**(start_values or {}), **inputs}.items():
        _check(execution.real_initial_value(index, ref(name), float(value)), f"setting {name}")
    result = _observe_and_run(
        execution, {name: (index, ref(name)) for name in outputs}, n_steps, step_ns
    )
    del execution, slave  # execution first: it owns the FMU instance
    return result


def run_libcosim_ssp(
    ssp_path, stop_time, step_size, outputs: list[str], log_level: str = "warning"
) -> dict[str, np.ndarray]:
    """Simulate the SSP archive ``ssp_path`` in libcosim with its own connections and
    component-level parameter bindings (libcosim ignores system-level ones).

    ``outputs`` are "Component.variable" names; the result has them and "time",
    ``round(stop_time / step_size) + 1`` samples from t = 0 as in ``run_libcosim``.
    ``log_level`` ("error" for runs whose FMU warnings are expected) is libcosim's
    process-wide stderr level.
    """
    require("libcosimpy", "cosim", "running in libcosim")
    from libcosimpy.CosimExecution import CosimExecution
    from libcosimpy.CosimLogging import CosimLogLevel, log_output_level

    step_ns, n_steps = _steps(stop_time, step_size)
    levels = CosimLogLevel.__members__
    if log_level.upper() not in levels:
        raise ValueError(f"log_level {log_level!r} is none of {', '.join(map(str.lower, levels))}")
    log_output_level(levels[log_level.upper()])
    execution = CosimExecution.from_ssp_file(str(Path(ssp_path).resolve()), step_size=step_ns)
    _check(execution.num_slaves() > 0, f"loading {ssp_path}")
    observed = {}
    for key in outputs:
        component, _, variable = key.partition(".")
        index = execution.slave_index_from_instance_name(component)
        _check(index >= 0, f"finding component {component} in {ssp_path}")
        observed[key] = (index, _real_references(execution, index, component)(variable))
    result = _observe_and_run(execution, observed, n_steps, step_ns)
    del execution
    return result
