"""The Python entry point: `cardan_joint.simulate.simulate` (see `host.simulate`)."""

from .host.simulate import DEFAULT_FMU, SimulationError, flat_columns, simulate

__all__ = ["DEFAULT_FMU", "SimulationError", "flat_columns", "simulate"]
