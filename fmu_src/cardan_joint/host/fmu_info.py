"""What the host tools know about an FMU, read from its modelDescription once:
variable names, causalities, units and display units, start values, FMI 3
arrays and the FMI 2 columns they split into. Every host tool (the CLI,
`simulate`, the instance helper, the plots) works from this, so a new model
needs nothing here.
"""

from __future__ import annotations

from dataclasses import dataclass
from math import prod
from pathlib import Path
from typing import Any

from ..names import UsageError, check_known


class MissingFMUError(FileNotFoundError):
    """The FMU file does not exist; the message names the command that builds it."""


class BadFMUError(UsageError):
    """A file that is not a readable FMU; the message names it and what is wrong."""


def read_model_description(fmu: str | Path) -> Any:
    """FMPy's model description of an FMU file or unzipped folder; MissingFMUError
    naming the build command, BadFMUError naming the file and the problem."""
    import zipfile

    from fmpy import read_model_description as fmpy_read

    path = require_fmu(fmu)
    try:
        return fmpy_read(str(path))
    except zipfile.BadZipFile as error:
        problem = f"not a zip archive ({error})"
    except KeyError:  # a zip archive without modelDescription.xml
        problem = "a zip archive without modelDescription.xml"
    except OSError as error:
        problem = error.strerror or str(error)
    except Exception as error:  # noqa: BLE001 - lxml's and FMPy's own errors, named
        problem = f"{type(error).__name__}: {' '.join(str(error).split())}"
    raise BadFMUError(f"{path} is not a readable FMU: {problem}")


def build_command(fmu: str | Path) -> str:
    """The `build_fmu.py` command that writes `fmu` (its model, FMI version,
    settings and folder from the file name and place)."""
    from ..models import MODELS

    path = Path(fmu)
    fmi3 = path.parent.name == "fmi3"
    dest = path.parent.parent if fmi3 else path.parent
    for key, spec in MODELS.items():
        for settings in spec.variants():
            if spec.default_name({**spec.default_settings, **settings}) == path.stem:
                flags = [f"--model {key}"]
                flags += [
                    f"--{k} {v}" for k, v in settings.items() if spec.default_settings[k] != v
                ]
                flags += ["--fmi-version 3"] if fmi3 else []
                flags += [] if dest == Path("dist") else [f"--dest {dest}"]
                return f"python build_fmu.py {' '.join(flags)}"
    return (
        f"python build_fmu.py --model MODEL --name {path.stem}"
        f"{' --fmi-version 3' if fmi3 else ''} (MODEL: one of {', '.join(MODELS)})"
    )


def require_fmu(fmu: str | Path) -> Path:
    """`fmu` as a Path, or MissingFMUError naming the build command."""
    path = Path(fmu)
    if not path.exists():
        raise MissingFMUError(f"{path} does not exist: build it with `{build_command(path)}`")
    return path


def array_columns(name: str, size: int) -> tuple[str, ...]:
    """The FMI 2 columns of an FMI 3 array: the FMI 2 variables a model's table
    has for it (its FMI 2 FMU has the same columns), else name_1, name_2, ..."""
    from ..models import array_rows

    rows = array_rows().get(name, ())
    return rows if len(rows) == size else tuple(f"{name}_{i + 1}" for i in range(size))


@dataclass(frozen=True)
class Variable:
    name: str
    causality: str
    unit: str
    display_unit: str  # the unit the plots use (the FMU's displayUnit, else its unit)
    factor: float  # value in display_unit = SI value * factor
    start: float | None
    size: int  # elements (an FMI 3 array); 1 for a scalar
    columns: tuple[str, ...]  # its names as FMI 2 result columns


class FmuInfo:
    """One FMU's variables, from its model description."""

    def __init__(self, model_description: Any, path: str | Path = "") -> None:
        self.path = Path(path)
        self.model_description = model_description
        self.model_name: str = model_description.modelName
        self.fmi3 = model_description.fmiVersion.startswith("3")
        factors = {
            (unit.name, display.name): float(display.factor)
            for unit in model_description.unitDefinitions
            for display in unit.displayUnits
        }
        self.variables: dict[str, Variable] = {}
        for v in model_description.modelVariables:
            size = prod(int(d.start) for d in getattr(v, "dimensions", None) or [])
            unit = v.unit or ""
            display = v.displayUnit if (unit, v.displayUnit) in factors else unit
            self.variables[v.name] = Variable(
                name=v.name,
                causality=v.causality,
                unit=unit,
                display_unit=display,
                factor=factors.get((unit, display), 1.0),
                start=None if v.start is None or size > 1 else float(v.start),
                size=size,
                columns=array_columns(v.name, size) if size > 1 else (v.name,),
            )
        # FMI 2 column name -> the variable holding it (itself, or its FMI 3 array).
        self.holder = {c: v for v in self.variables.values() for c in v.columns}

    @classmethod
    def read(cls, fmu: str | Path) -> FmuInfo:
        return cls(read_model_description(fmu), fmu)

    def names(self, *causalities: str) -> list[str]:
        """The variables of these causalities, in the FMU's order."""
        return [v.name for v in self.variables.values() if v.causality in causalities]

    def columns(self, *causalities: str) -> list[str]:
        """As `names`, each FMI 3 array as its FMI 2 columns."""
        return [c for v in self.variables.values() if v.causality in causalities for c in v.columns]

    @property
    def inputs(self) -> list[str]:
        return self.names("input")

    @property
    def outputs(self) -> list[str]:
        return self.names("output")

    def starts(self, *causalities: str) -> dict[str, float]:
        return {
            v.name: v.start
            for v in self.variables.values()
            if v.causality in causalities and v.start is not None
        }

    def check(self, names, causalities: tuple[str, ...], kind: str) -> None:
        """UnknownNameError unless every name is a variable (or an FMI 3 array's
        FMI 2 column) of these causalities."""
        valid = dict.fromkeys(self.columns(*causalities) + self.names(*causalities))
        for name in names:
            holder = self.holder.get(name) or self.variables.get(name)
            if name not in valid and holder is not None:
                raise UsageError(
                    f"{name!r} is an {holder.causality} of {self.model_name}, not an {kind}"
                )
        check_known(names, valid, f"{kind} of {self.model_name}")

    def fmu_names(self, columns) -> list[str]:
        """The FMU variables holding these columns (FMI 3: the arrays), in order."""
        return list(dict.fromkeys(self.holder[c].name if c in self.holder else c for c in columns))

    def display(self, column: str) -> tuple[float, str]:
        """(factor, unit): a column's SI value times factor is its value in its display unit."""
        variable = self.holder[column]
        return variable.factor, variable.display_unit
