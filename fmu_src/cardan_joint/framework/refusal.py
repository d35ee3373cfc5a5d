"""Why the joint refuses a step, an input or a parameter, as data.

A `Refusal` names the variable, its value, the limit it crosses, the time and a
reason code; `message` renders it as one readable sentence. The FMU runs a
separately shipped copy of this package, so the fields cross the FMU boundary
only as that sentence in the log: each reason has ONE template that both
renders the sentence and parses it back (`Refusal.from_message`), floats
written by `repr` so that they come back bit for bit.

A model's own reasons are its own: each is known by its model's folder (the
package of the enumeration that declares it) and its code, so a copied model
folder declares the same codes again without a clash. Messages carry no code:
a copy's message reads back as the reason of whichever folder registered that
template first, equal to it by code.
"""

import re
from dataclasses import dataclass, field
from enum import Enum

from ..units import RAD_TO_DEG


class Reason(str, Enum):
    """The reasons every stepped model shares; a model's own live in its folder's
    `refusals.py` (`register_reasons`)."""

    NOT_FINITE = "not_finite"  # NaN or infinite input or parameter
    OUT_OF_RANGE = "out_of_range"  # outside the variable's physical range
    STEP_SIZE = "step_size"  # step size not finite and > 0
    ANGLE_OVERFLOW = "angle_overflow"  # input angle advancing by > 1e15 rad
    SPEED_OVERFLOW = "speed_overflow"  # input speed beyond its range at step end


_OVERFLOW = (
    "input_speed = {input_speed} rad/s with input_acceleration = {input_acceleration} "
    "rad/s2 over a step of {step_size} s overflows: "
)
_SHARED_TEMPLATES: dict[Enum, str] = {
    Reason.NOT_FINITE: "{kind} {variable} = {value} {unit} is not a finite number "
    "(limit {limit} {unit})",
    Reason.OUT_OF_RANGE: "{kind} {variable} = {value} {unit} is outside its range "
    "[{low}, {high}] {unit} (limit {limit} {unit})",
    Reason.STEP_SIZE: "communication step size = {value} s must be a finite number > {limit} s",
    Reason.ANGLE_OVERFLOW: _OVERFLOW + "the input angle would advance by {value} rad, beyond "
    "the limit {limit} rad per step",
    Reason.SPEED_OVERFLOW: _OVERFLOW + "the speed would reach {value} rad/s at the step's end, "
    "beyond the limit {limit} rad/s",
}
# Fixed by the reason, so not written in the message.
_SHARED_IMPLIED: dict[Enum, tuple] = {
    Reason.STEP_SIZE: ("step_size", "s", ""),
    Reason.ANGLE_OVERFLOW: ("input_angle", "rad", "output"),
    Reason.SPEED_OVERFLOW: ("input_speed", "rad/s", "input"),
}


def _identity(reason: Enum) -> tuple:
    """(the package that declares the reason, its code): a model folder's codes
    are its own (str Enum members of equal codes are equal dict keys)."""
    return type(reason).__module__.rpartition(".")[0], reason.value


# Every declared reason by identity: the shared ones, then the models' own.
_REASONS: dict[tuple, Enum] = {_identity(reason): reason for reason in Reason}
_TEMPLATES = {_identity(reason): template for reason, template in _SHARED_TEMPLATES.items()}
_IMPLIED = {_identity(reason): fixed for reason, fixed in _SHARED_IMPLIED.items()}
_SHARED_CODES = frozenset(reason.value for reason in Reason)
_PREFIX = "t = {time} s: "
_FLOAT = r"-?(?:inf|nan|[0-9][0-9.e+-]*)"
_PLACEHOLDER = re.compile(r"\{(\w+)(?::deg)?\}")
_TEXT_FIELDS = {"kind": r"input|parameter", "variable": r"\w+", "unit": r"[\w./]+"}


def _pattern(template):
    """The regular expression that reads `template`'s fields back."""
    parts, seen, position = [], set(), 0
    for match in _PLACEHOLDER.finditer(template):
        parts.append(re.escape(template[position : match.start()]))
        name = match.group(1)
        if match.group(0).endswith(":deg}"):
            parts.append(r"[^ ()]+")  # derived from a parsed field
        elif name in seen:
            parts.append(f"(?P={name})")
        else:
            seen.add(name)
            parts.append(f"(?P<{name}>{_TEXT_FIELDS.get(name, _FLOAT)})")
        position = match.end()
    parts.append(re.escape(template[position:]))
    return re.compile("".join(parts))


_PATTERNS = {key: _pattern(_PREFIX + template) for key, template in _TEMPLATES.items()}


def register_reasons(reasons: type[Enum], templates: dict, implied: dict | None = None) -> None:
    """Declare a model's own reasons (a `str` Enum in its folder's `refusals.py`)
    with one message template each and the (variable, unit, kind) each fixes:
    they render and read back as the shared `Reason`s do, without a change here."""
    missing = [reason for reason in reasons if reason not in templates]
    if missing:
        raise ValueError(f"{reasons.__name__}.{missing[0].name} has no message template")
    for reason in reasons:
        known = _REASONS.get(_identity(reason))
        if reason.value in _SHARED_CODES or (known is not None and known is not reason):
            where = "the shared reasons" if reason.value in _SHARED_CODES else _identity(reason)[0]
            raise ValueError(f"reason code {reason.value!r} is already declared by {where}")
    for reason in reasons:
        key = _identity(reason)
        _REASONS[key], _TEMPLATES[key] = reason, templates[reason]
        _PATTERNS[key] = _pattern(_PREFIX + templates[reason])
    _IMPLIED.update({_identity(reason): fixed for reason, fixed in (implied or {}).items()})


def reasons() -> tuple:
    """Every reason declared so far: the shared ones and the imported models'."""
    return tuple(_REASONS.values())


@dataclass(frozen=True, eq=False)
class Refusal:
    """A refusal: `code` (a `Reason` or a model's own), the `variable` and its `value`, the `limit`
    crossed and its `unit`, the `time` (s) and the reason's further numbers in
    `details` (the range for OUT_OF_RANGE, the rates and the time into the step
    for a bend reached within it, the speed and step for an overflow)."""

    code: Enum
    variable: str
    value: float
    limit: float
    time: float
    unit: str
    details: dict = field(default_factory=dict)
    # "input", "parameter" or "output": named by the refusal, or fixed by its reason.
    kind: str = ""

    def __post_init__(self):
        implied = _IMPLIED.get(_identity(self.code))
        if not self.kind and implied and implied[0] == self.variable:
            object.__setattr__(self, "kind", implied[2])

    @property
    def text(self) -> str:
        """The explanation without the time."""
        fields = {
            "kind": self.kind,
            "variable": self.variable,
            "unit": self.unit,
            "value": self.value,
            "limit": self.limit,
            **self.details,
        }

        def render(match):
            value = fields[match.group(1)]
            if match.group(0).endswith(":deg}"):
                return f"{value * RAD_TO_DEG:.6g}"
            return repr(float(value)) if isinstance(value, (int, float)) else value

        return _PLACEHOLDER.sub(render, _TEMPLATES[_identity(self.code)])

    @property
    def message(self) -> str:
        return f"t = {float(self.time)!r} s: {self.text}"

    def __str__(self):
        return self.message

    def at(self, time: float) -> "Refusal":
        """The same refusal at another time."""
        return Refusal(
            self.code,
            self.variable,
            self.value,
            self.limit,
            time,
            self.unit,
            dict(self.details),
            self.kind,
        )

    def _key(self):
        names = sorted(self.details)
        numbers = (self.value, self.limit, self.time, *(self.details[n] for n in names))
        return (
            self.code,
            self.variable,
            self.unit,
            tuple(names),
            tuple(repr(float(x)) for x in numbers),
        )

    def __eq__(self, other):  # by repr, so that a NaN value equals itself
        return isinstance(other, Refusal) and self._key() == other._key()

    def __hash__(self):
        return hash(self._key())

    @classmethod
    def from_message(cls, text: str) -> "Refusal":
        """The refusal whose `message` appears in `text` (a log line may add to it).
        Raises ValueError if there is none."""
        for key, pattern in _PATTERNS.items():
            match = pattern.search(text)
            if match:
                found = match.groupdict()
                variable, unit, _ = _IMPLIED.get(key, (None, None, ""))
                variable, unit = variable or found.get("variable"), unit or found.get("unit")
                numbers = {
                    name: float(value) for name, value in found.items() if name not in _TEXT_FIELDS
                }
                return cls(
                    _REASONS[key],
                    variable,
                    numbers.pop("value"),
                    numbers.pop("limit"),
                    numbers.pop("time"),
                    unit,
                    numbers,
                    found.get("kind", ""),
                )
        raise ValueError(f"no refusal in {text!r}")


def crossed_limit(value: float, low: float, high: float) -> float:
    """The bound of [low, high] that `value` lies beyond (the upper one for NaN)."""
    return low if value < low else high
