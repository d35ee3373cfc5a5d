"""The C side of the translated values: three scalar types, tuples of them as
structs, and the literals that give C the very double Python holds."""

import math
import typing
from dataclasses import dataclass, field


class Untranslatable(Exception):
    """A construct the generator has no C for; the message names it and its file:line."""


@dataclass(frozen=True)
class Scalar:
    python: str  # float, int or bool
    c: str

    def __str__(self) -> str:
        return self.python


FLOAT = Scalar("float", "double")
# A Python int in the models is a count (whole turns): C's 64 bits hold every count a
# step can reach (an increment is refused beyond 1e15 rad).
INT = Scalar("int", "int64_t")
BOOL = Scalar("bool", "int")
SCALARS = {"float": FLOAT, "int": INT, "bool": BOOL}


@dataclass(frozen=True)
class Tuple:
    """A fixed-length tuple of scalars: a C struct with fields v0, v1, ...; a
    NamedTuple's fields are read by name too (`rule.exponent`). The names do not
    make it another type: a NamedTuple is the tuple of its items."""

    items: tuple[Scalar, ...]
    names: tuple[str, ...] | None = field(default=None, compare=False)

    def __str__(self) -> str:
        return f"tuple[{', '.join(map(str, self.items))}]"

    @property
    def c(self) -> str:
        return f"struct {self.tag}"

    @property
    def tag(self) -> str:
        # Named by its item types, run-length coded (t_i1f2: int, float, float), so
        # every tuple of one shape is one struct.
        parts: list[str] = []
        for item in self.items:
            letter = item.python[0]
            if parts and parts[-1][0] == letter:
                parts[-1] = f"{letter}{int(parts[-1][1:]) + 1}"
            else:
                parts.append(f"{letter}1")
        return "t_" + "".join(parts)

    def definition(self) -> str:
        fields = " ".join(f"{item.c} v{k};" for k, item in enumerate(self.items))
        return f"{self.c} {{ {fields} }};"


@dataclass(frozen=True)
class Table:
    """A module constant tuple of numbers of one type (Gauss nodes, weights): a
    static C array, indexed by a constant or by an int in its range."""

    item: Scalar
    size: int

    def __str__(self) -> str:
        return f"a constant table of {self.size} {self.item}s"


@dataclass(frozen=True)
class Rows:
    """A module constant tuple of tables of one item type, of any lengths (a
    quadrature's rules by their number of points): one static C array of every
    row and the start of each, read an item at a time (`NODES[n][i]`)."""

    item: Scalar
    sizes: tuple[int, ...]

    def __str__(self) -> str:
        return f"a constant table of {len(self.sizes)} rows of {self.item}s"


@dataclass(frozen=True)
class Function:
    """One of the model's functions passed as an argument (`torque_at`): bound at
    translation time, as a module is, so C calls its translation directly."""

    function: typing.Any


@dataclass(frozen=True)
class Module:
    """A Python module as a value (`math`, or a parameter bound to it)."""

    module: typing.Any


Type = Scalar | Tuple | Table | Rows | Module | Function


def arithmetic(left: Scalar, right: Scalar) -> Scalar:
    """Python's result type of + - * on two numbers (a bool counts as an int)."""
    return FLOAT if FLOAT in (left, right) else INT


def type_of_annotation(annotation: object, where: str) -> Scalar | Tuple:
    """The C type of an evaluated annotation: float, int, bool or a tuple of them."""
    if annotation in (float, int, bool):
        return SCALARS[annotation.__name__]
    if isinstance(annotation, type) and issubclass(annotation, tuple):
        names = getattr(annotation, "_fields", ())
        hints = typing.get_type_hints(annotation)
        items = tuple(hints.get(name) for name in names)
        if items and all(i in (float, int, bool) for i in items):
            return Tuple(tuple(SCALARS[i.__name__] for i in items), names)  # type: ignore[union-attr]
    if typing.get_origin(annotation) is tuple:
        items = typing.get_args(annotation)
        if items and Ellipsis not in items and all(i in (float, int, bool) for i in items):
            return Tuple(tuple(SCALARS[i.__name__] for i in items))
    raise Untranslatable(f"annotation {annotation!r} at {where}: C takes float, int, bool "
                         f"or a tuple of them")  # fmt: skip


def table_of(value: tuple, where: str) -> tuple[list[str], Table] | None:
    """The items' C texts and the table type of a tuple of numbers of one type."""
    items = [literal(item, where) for item in value]
    kinds = {kind for _, kind in items}
    if not items or len(kinds) != 1:
        return None
    return [text for text, _ in items], Table(kinds.pop(), len(items))


def rows_of(value: tuple, where: str) -> tuple[list[str], Rows] | None:
    """The items' C texts, row after row, and the type of a tuple of tables."""
    if not value or not all(type(row) is tuple for row in value):
        return None
    texts: list[str] = []
    kinds = set()
    for row in value:
        for item in row:
            text, kind = literal(item, where)
            texts.append(text)
            kinds.add(kind)
    if len(kinds) != 1:
        return None
    return texts, Rows(kinds.pop(), tuple(len(row) for row in value))


def literal(value: object, where: str) -> tuple[str, Scalar]:
    """C text of a Python constant and its type."""
    if isinstance(value, bool):
        return ("1" if value else "0"), BOOL
    if isinstance(value, int):
        if not -(2**63) < value < 2**63:
            raise Untranslatable(f"integer {value} at {where} does not fit 64 bits")
        return f"INT64_C({value})", INT
    if isinstance(value, float):
        if math.isnan(value):
            return "NAN", FLOAT
        if math.isinf(value):
            return ("INFINITY" if value > 0 else "(-INFINITY)"), FLOAT
        # The shortest repr reads back as the same double (C's literals round
        # correctly), and keeps the constant legible in the generated file.
        text = repr(value)
        return (f"({text})" if value < 0 else text), FLOAT
    raise Untranslatable(f"constant {value!r} at {where}: C takes floats, ints and bools")
