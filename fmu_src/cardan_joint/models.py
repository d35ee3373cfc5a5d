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

FMU_DIR = Path(__file__).resolve().parent / "fmu"


class StartValueError(ValueError):
    """A start value is unknown or cannot run; the message says which and why."""


def _check_values(values: Mapping[str, float], table, make, owner: str = "") -> None:
    """Raise StartValueError unless `values` name inputs and parameters of `table`
    only and the model `make(**values)` can run with them."""
    unknown = sorted(set(values) - set(table.INPUTS) - set(table.PARAMETERS))
    if unknown:
        raise StartValueError(
            f"cannot set start value of {', '.join(unknown)}: only inputs "
            f"and parameters{owner} have start values"
        )
    model = make(**values)
    problem = model.parameter_problem() or model.input_problem()
    if problem:
        raise StartValueError(f"invalid start values: {problem.text}")


def _check_propshaft_start_values(values: Mapping[str, float], settings: Mapping) -> None:
    from .physics.propshaft import Propshaft
    from .propshaft_variables import JOINTS, propshaft_table

    joints = settings.get("joints")
    if joints not in JOINTS:
        raise StartValueError(
            f"--joints {joints!r}: the Propshaft is built for {', '.join(map(str, JOINTS))} joints"
        )
    _check_values(
        values,
        propshaft_table(joints),
        lambda **v: Propshaft(joints, **v),
        f" of the {joints}-joint Propshaft",
    )


def _propshaft_name(settings: Mapping) -> str:
    joints = settings.get("joints", 2)
    return "Propshaft" if joints == 2 else f"Propshaft{joints}"


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
        check_start_values=_check_propshaft_start_values,
        default_settings={"joints": 2},
        name_for=_propshaft_name,
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
}


def model(key: str) -> Model:
    try:
        return MODELS[key]
    except KeyError:
        raise StartValueError(f"no model {key!r}: choose one of {', '.join(MODELS)}") from None
