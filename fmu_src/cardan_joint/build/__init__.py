"""Build the project's FMUs (`builder`), make their archives reproducible
(`archive`) and write the fmi-cross-check layout (`cross_check`)."""

from .builder import DEFAULT_MODEL, FMI_VERSIONS, RUNTIME, BuildError, build, main

__all__ = ["DEFAULT_MODEL", "FMI_VERSIONS", "RUNTIME", "BuildError", "build", "main"]
