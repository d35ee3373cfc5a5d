"""What a variable table is made of: units, variables and a model's table.

Pure data types with the lookups every wrapper needs (FMI 2 and FMI 3
registration, model descriptions; tools/model_pages.py renders the pages'
tables); the tables themselves are each model folder's `variables`
(`models/<name>/variables.py`). No FMI import: the physics reads its defaults from them.
"""

import os
import re
from collections.abc import Mapping
from dataclasses import dataclass

_IN, _PAR, _OUT = "input", "parameter", "output"


@dataclass(frozen=True)
class Unit:
    name: str
    exponents: tuple  # ((base unit, exponent), ...) of FMI's BaseUnit
    display: tuple = ()  # ((display unit, factor), ...): display = factor * value
    factor: float = 1.0  # SI value = factor * value (FMI BaseUnit factor), e.g. 1/h


@dataclass(frozen=True)
class Variable:
    name: str
    causality: str  # "input", "parameter" or "output"
    unit: str
    description: str
    start: float | None = None
    display_unit: str | None = None
    min: float | None = None
    max: float | None = None
    depends_on: tuple = ()  # outputs only

    @property
    def variability(self) -> str:
        return "fixed" if self.causality == "parameter" else "continuous"

    @property
    def initial(self) -> str | None:
        return {"parameter": "exact", "output": "calculated"}.get(self.causality)


class VariableTable:
    """One model's variables with the lookups every wrapper needs. A model's
    `variables.py` module may itself be its table (the same attribute names);
    others build one (e.g. `units.table_of`)."""

    def __init__(self, variables, units: Mapping[str, Unit], array_stems: tuple = ()):
        """`units`: the unit definitions (name -> Unit) its description declares;
        `array_stems`: the vectors FMI 3 declares as arrays (`fmi3_groups`)."""
        self.VARIABLES = tuple(variables)
        self.ARRAY_STEMS = tuple(array_stems)
        self.BY_NAME = {v.name: v for v in self.VARIABLES}
        self.INPUTS = _names(self.VARIABLES, _IN)
        self.PARAMETERS = _names(self.VARIABLES, _PAR)
        self.OUTPUTS = _names(self.VARIABLES, _OUT)
        self.UNITS = dict(units)

    def start_values(self) -> dict:
        return start_values(self.VARIABLES)

    def fmi3_variables(self) -> tuple:
        """Its FMI 3 variables: arrays where ARRAY_STEMS says, else scalars."""
        return fmi3_groups(self.VARIABLES, self.ARRAY_STEMS)


def _names(variables, causality):
    return tuple(v.name for v in variables if v.causality == causality)


def start_values(variables) -> dict:
    return {v.name: v.start for v in variables if v.start is not None}


@dataclass(frozen=True)
class Group:
    """One FMI 3 variable: a scalar row, or the rows of one array in element order.
    Every attribute but the name and description is the rows' common one."""

    name: str
    rows: tuple

    def __getattr__(self, attribute):
        if attribute.startswith("_"):  # copy/pickle probe before `rows` exists
            raise AttributeError(attribute)
        return getattr(self.rows[0], attribute)

    @property
    def description(self) -> str:
        """The rows' common prefix (to a word) with each element's rest, in order."""
        texts = [row.description for row in self.rows]
        if len(texts) == 1:
            return texts[0]
        common = os.path.commonprefix(texts)
        common = common[: common.rfind(" ") + 1]
        return common + " / ".join(text[len(common) :] for text in texts)


def _group(variables: tuple, stem: str) -> "Group":
    rows = tuple(v for v in variables if re.fullmatch(re.escape(stem) + r"_\d", v.name))
    first = variables.index(rows[0])
    shared = ("causality", "unit", "display_unit", "min", "max", "depends_on", "start")
    assert rows == variables[first : first + len(rows)], f"{stem}: rows must be consecutive"
    assert all(getattr(r, a) == getattr(rows[0], a) for r in rows for a in shared), (
        f"{stem}: the elements of an array share causality, unit, range and dependencies"
    )
    return Group(stem, rows)


def fmi3_groups(variables: tuple, array_stems: tuple = ()) -> tuple:
    """The FMI 3 variables in table order: one array of the rows `<stem>_<i>` for
    each of `array_stems` (FMI 2 has one row per element), else scalars."""
    arrays = {g.rows[0].name: g for g in (_group(variables, stem) for stem in array_stems)}
    in_array = {row.name for g in arrays.values() for row in g.rows}
    return tuple(
        arrays.get(v.name) or Group(v.name, (v,))
        for v in variables
        if v.name in arrays or v.name not in in_array
    )
