"""Optional dependencies (pyproject's extras): one clear message when one is missing.

The core (build, simulate, the FMUs) needs none of them; a Dask sweep, the
libcosim runs and Parquet output do, and a user who has not installed them
should read which extra to install, not an import traceback.
"""

from __future__ import annotations

import importlib


class MissingExtra(ImportError):
    """An optional dependency is not installed; the message says how to install it."""


def require(module: str, extra: str, purpose: str) -> None:
    """Raise MissingExtra unless ``module`` imports; ``extra`` is its pyproject extra."""
    try:
        importlib.import_module(module)
    except ImportError as error:
        raise MissingExtra(
            f"{purpose} needs {module}, which is not installed ({error}); install it with "
            f"pip install -e '.[{extra}]' in a checkout or pip install "
            f"'cardan-joint-fmu[{extra}]'"
        ) from error
