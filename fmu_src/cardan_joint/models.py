"""The FMUs this project builds: one entry per model, read by the build.

An entry names the pythonfmu script template for each FMI version it can be
built for, how to name a build from its settings (e.g. the number of joints),
and how to check start values before anything is packed: an FMU whose defaults
cannot run would only fail later, in someone's master. Pure data plus small
checks; the build itself lives in `build.py`.
"""

import importlib
from collections.abc import Callable, Mapping
from dataclasses import dataclass, field
from pathlib import Path

from .names import unknown

FMU_DIR = Path(__file__).resolve().parent / "fmu"


class StartValueError(ValueError):
    """A start value is unknown or cannot run; the message says which and why."""


def _check_values(values: Mapping[str, float], table, make, owner: str = "") -> None:
    """Raise StartValueError unless `values` name inputs and parameters of `table`
    only and the model `make(**values)` can run with them."""
    settable = set(table.INPUTS) | set(table.PARAMETERS)
    strangers = sorted(set(values) - settable)
    if strangers:
        kind = f"input or parameter{owner} (only they have start values)"
        raise StartValueError(f"cannot set a start value: {unknown(strangers[0], settable, kind)}")
    model = make(**values)
    problem = model.parameter_problem() or model.input_problem()
    if problem:
        raise StartValueError(f"invalid start values: {problem.text}")


def _propshaft_checker(key: str, module: str, table: str):
    """Start-value check for the N-joint model `key`, class `physics.<module>.<key>`
    (the Propshaft, the CompliantPropshaft), its table `<table module>.<function>`
    of the number of joints."""

    def check(values: Mapping[str, float], settings: Mapping) -> None:
        from .propshaft_variables import JOINTS

        joints = settings.get("joints")
        if joints not in JOINTS:
            raise StartValueError(
                f"--joints {joints!r}: the {key} is built for {', '.join(map(str, JOINTS))} joints"
            )
        model_class = getattr(importlib.import_module(f"{__package__}.physics.{module}"), key)
        table_module, table_function = table.rsplit(".", 1)
        table_of = getattr(importlib.import_module(f"{__package__}.{table_module}"), table_function)
        make = lambda **v: model_class(joints, **v)  # noqa: E731
        _check_values(values, table_of(joints), make, f" of the {joints}-joint {key}")

    return check


def _propshaft_namer(key: str):
    def name_for(settings: Mapping) -> str:
        joints = settings.get("joints", 2)
        return key if joints == 2 else f"{key}{joints}"

    return name_for


def _start_value_checker(module: str, class_name: str):
    """Start-value check for the stepped model `physics.<module>.<class_name>`
    (imported at the check: the physics stays out of this module's import)."""

    def check(values: Mapping[str, float], settings: Mapping) -> None:
        model_class = getattr(
            importlib.import_module(f"{__package__}.physics.{module}"), class_name
        )
        _check_values(values, model_class.table, model_class)

    return check


@dataclass(frozen=True)
class Model:
    """How to build one model.

    `scripts` maps an FMI major version to the pythonfmu script template; the
    build renames the template's first class to the model name and writes the
    start values into its `start_overrides = {}` line and the settings into
    its `build_settings = {}` line (when it has one).
    """

    key: str
    scripts: dict[int, Path]
    check_start_values: Callable[[Mapping[str, float], Mapping], None]
    default_settings: Mapping = field(default_factory=dict)
    # Model name for given settings (default: the key).
    name_for: Callable[[Mapping], str] | None = None

    def default_name(self, settings: Mapping) -> str:
        return self.name_for(settings) if self.name_for else self.key


MODELS: dict[str, Model] = {
    "UniversalJoint": Model(
        key="UniversalJoint",
        scripts={2: FMU_DIR / "UniversalJoint.py", 3: FMU_DIR / "UniversalJoint3.py"},
        check_start_values=_start_value_checker("model", "CardanJoint"),
    ),
    "Propshaft": Model(
        key="Propshaft",
        scripts={2: FMU_DIR / "Propshaft.py"},
        check_start_values=_propshaft_checker(
            "Propshaft", "propshaft", "propshaft_variables.propshaft_table"
        ),
        default_settings={"joints": 2},
        name_for=_propshaft_namer("Propshaft"),
    ),
    "Motor": Model(
        key="Motor",
        scripts={2: FMU_DIR / "Motor.py"},
        check_start_values=_start_value_checker("driveline", "Motor"),
    ),
    "Load": Model(
        key="Load",
        scripts={2: FMU_DIR / "Load.py"},
        check_start_values=_start_value_checker("driveline", "Load"),
    ),
    "InertiaLoad": Model(
        key="InertiaLoad",
        scripts={2: FMU_DIR / "InertiaLoad.py"},
        check_start_values=_start_value_checker("inertia_load", "InertiaLoad"),
    ),
    "CompliantJoint": Model(
        key="CompliantJoint",
        scripts={2: FMU_DIR / "CompliantJoint.py"},
        check_start_values=_start_value_checker("compliant", "CompliantJoint"),
    ),
    "CompliantPropshaft": Model(
        key="CompliantPropshaft",
        scripts={2: FMU_DIR / "CompliantPropshaft.py"},
        check_start_values=_propshaft_checker(
            "CompliantPropshaft",
            "compliant_propshaft",
            "compliant_variables.compliant_propshaft_table",
        ),
        default_settings={"joints": 2},
        name_for=_propshaft_namer("CompliantPropshaft"),
    ),
}


def model(key: str) -> Model:
    try:
        return MODELS[key]
    except KeyError:
        raise StartValueError(f"no model {key!r}: choose one of {', '.join(MODELS)}") from None
