"""The model API: what every model's physics object gives its FMU slave
(`fmi/core.py`, `fmi/fast_path.py`), stated once and checked by mypy (each
spec's `make` returns one, `stepped` takes a class that makes one), and what
the framework reads of a model's variable table."""

from collections.abc import Mapping, Sequence
from typing import Protocol

from ..variable_schema import Variable
from .refusal import Refusal


class Table(Protocol):
    """What the checks read of a variable table: the `variables` module itself
    or a `variables.VariableTable` (read-only, so either one matches)."""

    @property
    def BY_NAME(self) -> Mapping[str, Variable]: ...

    @property
    def INPUTS(self) -> tuple[str, ...]: ...

    @property
    def PARAMETERS(self) -> tuple[str, ...]: ...

    @property
    def OUTPUTS(self) -> tuple[str, ...]: ...

    def start_values(self) -> dict[str, float]: ...


class Stepped(Protocol):
    """A stepped model: inputs and parameters as attributes named as in its `table`;
    parameters are checked once per `start` (`parameter_fault`), inputs at every
    step; a refusal is a `Refusal` returned, never raised, and changes nothing
    but the inputs."""

    time: float
    parameter_fault: Refusal | None

    @property
    def table(self) -> Table:
        """The model's variable table (read-only)."""

    def start(self, time: float) -> None:
        """Clock at `time`, state from the parameters (checked here, once)."""

    def parameter_problem(self) -> Refusal | None: ...

    def input_problem(self, step_size: float = 0.0) -> Refusal | None: ...

    def invalid_inputs(self) -> set:
        """Names of the inputs unusable now."""

    def inputs(self) -> tuple[float, ...]:
        """The inputs' values, in the table's order."""

    def set_inputs(self, values: Sequence[float]) -> None: ...

    def step(self, step_size: float) -> Refusal | None: ...

    def outputs(self) -> tuple:
        """The outputs' values, in the table's order."""

    def run(self, time: float, step_size: float, inputs: Sequence[float]) -> "tuple | Refusal":
        """The FMU's step: `set_inputs`, then `step` from `time`, then the pair
        (`outputs`, `inputs` after the step: those polynomial over it have moved),
        or the Refusal (the clock back where it was)."""

    def state(self) -> dict: ...

    def restore(self, state: dict) -> None:
        """Take a `state()`: all or nothing."""
