"""The FMUs this project builds, discovered from their folders.

Every subpackage of `models/` with a `spec.py` defining `MODEL` (a `Model`) is
a model: its folder holds its variable table, physics, refusal reasons and this
spec. The spec declares the FMU name once, the FMI versions it builds for, the
FMU's description, how to make its physics object from start values and build
settings (e.g. the number of joints), and how to name a build from its
settings. The start values are checked here before anything is packed: an FMU
whose defaults cannot run would only fail later, in someone's master. Pure data
plus small checks: no FMI import (the FMU's slave reads its own folder's spec).
"""

import importlib
from collections.abc import Callable, Mapping
from dataclasses import dataclass, field, replace
from functools import cache
from pathlib import Path
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from ..physics.api import Stepped

MODELS_DIR = Path(__file__).resolve().parent


class StartValueError(ValueError):
    """A start value is unknown or cannot run; the message says which and why."""


@dataclass(frozen=True)
class Model:
    """How to build one model and what its FMU slave maps onto.

    `make(settings, **start_values)` returns the physics object (the model API,
    `physics.api.Stepped`); `table_for(settings)` its variable table. `live_outputs` are
    the leading outputs that follow the state while an input is invalid;
    `owner` is what "stays put" in the slave's messages.
    """

    key: str
    description: str
    table_for: Callable[[Mapping], Any]
    make: "Callable[..., Stepped]"
    live_outputs: tuple[str, ...] = ()
    owner: str = "model"
    fmi_versions: tuple[int, ...] = (2, 3)
    default_settings: Mapping = field(default_factory=dict)
    # Raises StartValueError for settings the model cannot be built with.
    check_settings: Callable[[Mapping], None] | None = None
    # Model name for given settings (default: the key).
    name_for: Callable[[Mapping], str] | None = None
    # The physics object's `warnings()` are logged when initialization ends.
    warns: bool = False
    folder: str = ""  # the model's folder under models/ (set by discovery)

    def default_name(self, settings: Mapping) -> str:
        return self.name_for(settings) if self.name_for else self.key

    def check_start_values(self, values: Mapping[str, float], settings: Mapping) -> None:
        """Raise StartValueError unless `values` name inputs and parameters only and
        the model built with `settings` can run with them (the physics' own checks:
        its unknown-name check names the nearest valid names)."""
        from ..physics.values import UnknownVariableError

        if self.check_settings:
            self.check_settings(settings)
        try:
            model = self.make(settings, **values)
        except UnknownVariableError as error:
            raise StartValueError(
                f"cannot set a start value: {error} (only inputs and parameters have one)"
            ) from None
        problem = model.parameter_problem() or model.input_problem()
        if problem:
            raise StartValueError(f"invalid start values: {problem.text}")


def stepped(model_class: "Callable[..., Stepped]") -> "Callable[..., Stepped]":
    """`Model.make` of a model whose physics takes start values only."""
    return lambda settings, **values: model_class(**values)


@cache
def discover() -> dict[str, Model]:
    """Every model under models/, by FMU name (its key)."""
    found = {}
    for spec_file in sorted(MODELS_DIR.glob("*/spec.py")):
        folder = spec_file.parent.name
        spec = importlib.import_module(f"{__name__}.{folder}.spec").MODEL
        found[spec.key] = replace(spec, folder=folder)
    return found


def __getattr__(name: str):
    if name == "MODELS":
        return discover()
    raise AttributeError(name)


def model(key: str) -> Model:
    models = discover()
    try:
        return models[key]
    except KeyError:
        raise StartValueError(f"no model {key!r}: choose one of {', '.join(models)}") from None
