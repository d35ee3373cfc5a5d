"""The FMUs this project builds, discovered from their folders.

Every subpackage of `models/` with a `spec.py` defining `MODEL` (a `Model`) is
a model: its folder holds its variable table, physics, refusal reasons, its
page (README.md: the equations' contract and the generated variable table),
its reference run's files (<key>_in.csv, _ref.opt, _ref.csv) and this spec.
Everything generic (build, hosts, docs index, checks) walks what `discover`
finds and names no model. The spec declares the FMU name once, the FMI versions it builds for, the
FMU's description, how to make its physics object from start values and build
settings (e.g. the number of joints, their choices and help), how to name a
build from its settings, and its reference run (`ReferenceRun`). The start
values are checked here before anything is packed: an FMU whose defaults
cannot run would only fail later, in someone's master. Pure data
plus small checks: no FMI import (the FMU's slave reads its own folder's spec).
"""

import importlib
from collections.abc import Callable, Mapping
from dataclasses import dataclass, field, replace
from functools import cache
from pathlib import Path
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from ..framework.api import Stepped

MODELS_DIR = Path(__file__).resolve().parent


class StartValueError(ValueError):
    """A start value is unknown or cannot run; the message says which and why."""


# The fmi-cross-check rules' run options, which every reference run uses unless
# its spec says otherwise.
REFERENCE_OPTIONS = {"StartTime": 0.0, "StopTime": 1.0, "StepSize": 1e-3, "RelTol": 1e-6}


@dataclass(frozen=True)
class ReferenceRun:
    """A model's reference run, computed by the physics (build/cross_check.py)
    at its default settings and start values: inputs as rows (time, then the
    table's inputs in order) interpolated linearly, the outputs recorded (at
    most 9: the cross-check rules' 10 columns with the time), the run options."""

    input_rows: tuple[tuple[float, ...], ...]
    outputs: tuple[str, ...]
    options: Mapping[str, float] = field(default_factory=lambda: dict(REFERENCE_OPTIONS))


@dataclass(frozen=True)
class Model:
    """How to build one model and what its FMU slave maps onto.

    `make(settings, **start_values)` returns the physics object (the model API,
    `framework.api.Stepped`); `table_for(settings)` its variable table. `live_outputs` are
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
    # Outputs to warn of, once each, past a limit (`framework.watches.Watch` rows).
    watches: tuple = ()
    # Its reference run, if it has one (files in its folder, checked by the tests).
    reference: ReferenceRun | None = None
    # Build settings' choices and help (`--joints N`): the build command offers
    # `--<setting>` for every setting a model declares in `default_settings`.
    setting_choices: Mapping[str, tuple] = field(default_factory=dict)
    setting_help: Mapping[str, str] = field(default_factory=dict)
    # The function the build translates into the FMU's runtime for these settings
    # (docs/codegen.md: it takes (time, h, the model's step_state(), inputs,
    # parameters) by the table's names), or None: the step runs in Python.
    step: Callable[[Mapping], Callable | None] | None = None
    folder: str = ""  # the model's folder under models/ (set by discovery)

    @property
    def path(self) -> Path:
        """The model's folder: its page, reference files and code."""
        return MODELS_DIR / self.folder

    @property
    def page(self) -> Path:
        """Its page: the equations' contract and the generated variable table."""
        return self.path / "README.md"

    def table(self, settings: Mapping | None = None) -> Any:
        """Its variable table at `settings` (default: its default settings)."""
        return self.table_for({**self.default_settings, **(settings or {})})

    def variants(self) -> list[dict]:
        """Every combination of its settings' choices (one `{}` if it has none)."""
        variants: list[dict] = [{}]
        for name, choices in self.setting_choices.items():
            variants = [{**v, name: choice} for v in variants for choice in choices]
        return variants

    def default_name(self, settings: Mapping) -> str:
        return self.name_for(settings) if self.name_for else self.key

    def check_start_values(self, values: Mapping[str, float], settings: Mapping) -> None:
        """Raise StartValueError unless `values` name inputs and parameters only and
        the model built with `settings` can run with them (the physics' own checks:
        its unknown-name check names the nearest valid names)."""
        from ..framework.values import UnknownVariableError

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


@cache
def array_rows() -> dict[str, tuple[str, ...]]:
    """FMI 3 array name -> the FMI 2 variables it holds, in element order, over
    every model's table (a host splits an FMI 3 result into FMI 2 columns by it)."""
    rows: dict[str, tuple[str, ...]] = {}
    for spec in discover().values():
        for settings in spec.variants():
            for group in spec.table(settings).fmi3_variables():
                names = tuple(row.name for row in group.rows)
                if len(names) > 1 and rows.setdefault(group.name, names) != names:
                    raise ValueError(f"two models' FMI 3 arrays {group.name!r} differ")
    return rows


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
