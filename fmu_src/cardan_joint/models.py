"""The FMUs this project builds: one entry per model, read by the build.

An entry names the pythonfmu script template for each FMI version it can be
built for, how to name a build from its settings (e.g. the number of joints),
and how to check start values before anything is packed: an FMU whose defaults
cannot run would only fail later, in someone's master. Pure data plus small
checks; the build itself lives in `build.py`.
"""

from dataclasses import dataclass, field
from pathlib import Path
from typing import Callable, Dict, Mapping, Optional

from . import variables as joint_table

FMU_DIR = Path(__file__).resolve().parent / "fmu"


class StartValueError(ValueError):
    """A start value is unknown or cannot run; the message says which and why."""


def _check_joint_start_values(values: Mapping[str, float], settings: Mapping) -> None:
    from .physics.model import CardanJoint

    settable = set(joint_table.INPUTS) | set(joint_table.PARAMETERS)
    unknown = sorted(set(values) - settable)
    if unknown:
        raise StartValueError(f"cannot set start value of {', '.join(unknown)}: "
                              f"only inputs and parameters have start values")
    joint = CardanJoint(**values)
    problem = joint.parameter_problem() or joint.input_problem()
    if problem:
        raise StartValueError(f"invalid start values: {problem}")


def _component_start_value_checker(class_name: str):
    """Start-value check for the stepped model `physics.driveline.<class_name>`."""
    def check(values: Mapping[str, float], settings: Mapping) -> None:
        from .physics import driveline

        model_class = getattr(driveline, class_name)
        table = model_class.table
        unknown = sorted(set(values) - set(table.INPUTS) - set(table.PARAMETERS))
        if unknown:
            raise StartValueError(f"cannot set start value of {', '.join(unknown)}: "
                                  f"only inputs and parameters have start values")
        component = model_class(**values)
        problem = component.parameter_fault or component.input_problem()
        if problem:
            raise StartValueError(f"invalid start values: {problem}")
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
    scripts: Dict[int, Path]
    check_start_values: Callable[[Mapping[str, float], Mapping], None]
    default_settings: Mapping = field(default_factory=dict)
    # Model name for given settings (default: the key).
    name_for: Optional[Callable[[Mapping], str]] = None

    def default_name(self, settings: Mapping) -> str:
        return self.name_for(settings) if self.name_for else self.key


MODELS: Dict[str, Model] = {
    "UniversalJoint": Model(
        key="UniversalJoint",
        scripts={2: FMU_DIR / "UniversalJoint.py"},
        check_start_values=_check_joint_start_values,
    ),
    "Motor": Model(
        key="Motor",
        scripts={2: FMU_DIR / "Motor.py"},
        check_start_values=_component_start_value_checker("Motor"),
    ),
    "Load": Model(
        key="Load",
        scripts={2: FMU_DIR / "Load.py"},
        check_start_values=_component_start_value_checker("Load"),
    ),
}


def model(key: str) -> Model:
    try:
        return MODELS[key]
    except KeyError:
        raise StartValueError(f"no model {key!r}: choose one of {', '.join(MODELS)}") from None
