"""Build the project's FMUs (`builder`), make their archives reproducible
(`archive`), write the fmi-cross-check layout (`cross_check`) and parse the
command line (`command`)."""

from .builder import DEFAULT_MODEL, FMI_VERSIONS, RUNTIME, BuildError, build
from .command import main

__all__ = ["DEFAULT_MODEL", "FMI_VERSIONS", "RUNTIME", "BuildError", "build", "main"]
