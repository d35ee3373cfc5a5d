"""Run an SSP system in Ecos through its Python API ``ecospy`` (the ``ecos`` extra).

``pip install -e '.[ecos]'`` installs it (checked with ecospy 0.7.2, whose wheel
bundles ``libecosc.so``, the Ecos C API, and the ``ecos`` command line). Things
worth knowing, read in Ecos's sources and measured:

* ``libecosc.so`` needs oneTBB's ``libtbb.so.12``, which no system here has. The
  ``tbb`` wheel installs it in the environment's ``lib/`` folder, where the
  dynamic linker does not look; it is loaded first by its path, so that
  ``libecosc.so`` finds it loaded (by its soname) when ecospy imports.
* Ecos gathers the component-level parameter bindings into sets by the name
  inside each ``.ssv`` and applies at most one set, the one named at
  initialisation (``init(parameter_set=...)``, the CLI's ``--parameterSet``);
  with none named it applies none (``simulation::init``), and it ignores
  system-level bindings. Our SSPs name every component's set after the system
  (``host.ssp``), so that one name applies every parameter, and the driveline's
  FMUs start at the bound values (``driveline_system.build_fmus``), so that
  ``init()`` with no name runs the same system.
* Identifiers are ``"Component::variable"``.
* At initialisation the initial outputs are passed through before the first
  step (as libcosim does), then every step transfers the outputs of the step
  just taken (explicit, Jacobi-type coupling).
* A refused step (``fmi2Discard``) does not stop Ecos: the status is ignored,
  the FMU holds its outputs, and only Ecos's debug log shows it.
* ecospy puts its binaries' folder on ``PATH`` when it is imported (its own
  doing, for its ``proxyfmu`` helper); the log level set here is Ecos's own,
  process-wide.
"""

from __future__ import annotations

import ctypes
import sys
from pathlib import Path

import numpy as np

from ..extras import MissingExtra, require

TBB = "libtbb.so.12"


def _load_tbb() -> None:
    """Make ``libtbb.so.12`` loaded in this process, from the environment's lib/
    folder unless the dynamic linker finds one of its own."""
    try:
        ctypes.CDLL(TBB)
        return
    except OSError:
        pass
    candidates = [Path(prefix) / "lib" / TBB for prefix in (sys.prefix, sys.base_prefix)]
    for path in candidates:
        if path.is_file():
            ctypes.CDLL(str(path), mode=ctypes.RTLD_GLOBAL)
            return
    raise MissingExtra(
        f"Ecos needs {TBB}, found neither by the dynamic linker nor in "
        f"{', '.join(map(str, candidates))}; install the ecos extra (it brings the tbb wheel)"
    )


def require_ecos(purpose: str = "running in Ecos"):
    """The ``ecospy`` module, its ``libtbb.so.12`` loaded first; MissingExtra (naming
    `purpose`) without them."""
    _load_tbb()
    require("ecospy", "ecos", purpose)
    import ecospy

    return ecospy


def run_ecos_ssp(
    ssp_path,
    stop_time: float,
    step_size: float,
    outputs: list[str],
    parameter_set: str | None,
    log_level: str = "warn",
) -> dict[str, np.ndarray]:
    """Simulate the SSP archive ``ssp_path`` in Ecos with its connections, applying
    the parameter set named ``parameter_set``.

    ``outputs`` are "Component.variable" names; the result has them and "time",
    ``round(stop_time / step_size) + 1`` samples from t = 0 (the initial outputs)
    on, as ``cosim.run_libcosim_ssp`` gives. Times are k h exactly: Ecos adds the
    step to its clock, which drifts by rounding.
    """
    n_steps = round(stop_time / step_size) if step_size > 0 else 0
    if n_steps < 1 or abs(n_steps * step_size - stop_time) > 1e-9 * stop_time:
        raise ValueError(
            f"stop_time {stop_time} is not a positive whole number of steps {step_size}"
        )
    ecospy = require_ecos()
    ecospy.EcosLib.set_log_level(log_level)
    identifiers = {key: "::".join(key.split(".", 1)) for key in outputs}
    result = {key: np.empty(n_steps + 1) for key in outputs}
    with ecospy.EcosSimulation(ssp_path=str(Path(ssp_path).resolve()), step_size=step_size) as sim:
        sim.init(parameter_set=parameter_set)
        for k in range(n_steps + 1):
            if k:
                sim.step()
            for key, identifier in identifiers.items():
                result[key][k] = sim.get_real(identifier)
        sim.terminate()
    return {"time": np.arange(n_steps + 1) * step_size, **result}
