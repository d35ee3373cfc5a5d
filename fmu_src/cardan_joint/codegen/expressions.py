"""Python expressions as C expressions of the same IEEE operations in the same
order: every binary operation parenthesized as the Python tree groups it, a
tuple-valued operand held in a temporary so it is evaluated once."""

import ast
import builtins
import math
import types
from typing import Any

from .types import (
    BOOL,
    FLOAT,
    INT,
    Function,
    Module,
    Rows,
    Scalar,
    Table,
    Tuple,
    Type,
    Untranslatable,
    arithmetic,
    literal,
    rows_of,
    table_of,
)

# Python operator -> C operator, for operands of matching type (the test of the
# generated step mutates this table to prove it sees a wrong translation).
BINARY = {ast.Add: "+", ast.Sub: "-", ast.Mult: "*", ast.Div: "/"}
BITWISE = {ast.BitAnd: "&", ast.BitOr: "|", ast.BitXor: "^", ast.LShift: "<<", ast.RShift: ">>"}
COMPARE = {ast.Lt: "<", ast.LtE: "<=", ast.Gt: ">", ast.GtE: ">=", ast.Eq: "==", ast.NotEq: "!="}

# math functions C's library computes as CPython does (CPython calls the same libm
# for these): name -> (argument count, result type).
MATH_CALLS = {
    **{name: (1, FLOAT) for name in (
        "sin", "cos", "tan", "asin", "acos", "atan", "sinh", "cosh", "tanh", "asinh",
        "acosh", "atanh", "exp", "expm1", "log", "log1p", "log10", "log2", "sqrt", "fabs",
        "erf", "erfc", "cbrt",
    )},
    "atan2": (2, FLOAT), "copysign": (2, FLOAT), "fmod": (2, FLOAT), "pow": (2, FLOAT),
    "floor": (1, INT), "ceil": (1, INT), "trunc": (1, INT),
    "isfinite": (1, BOOL), "isnan": (1, BOOL), "isinf": (1, BOOL),
}  # fmt: skip
MATH_CONSTANTS = ("pi", "e", "tau", "inf", "nan")
# Why the math functions not listed are refused, where it is not just "not yet".
MATH_REFUSED = {
    "hypot": "CPython computes math.hypot itself, not as the C library's hypot does: "
    "write sqrt(x * x + y * y) or a scaled form both sides compute alike",
    "fsum": "math.fsum keeps an exact partial sum list: write a compensated sum",
}


def parenthesized(text: str) -> str:
    """Keep Python's grouping (the mutation test drops it to prove the test sees it)."""
    return f"({text})"


class Expressions:
    """Mixed into `functions.FunctionTranslator`, which provides the scope."""

    locals: dict[str, Scalar | Tuple]
    c_names: dict[str, str]
    unrolled: dict[str, int]
    bound: dict[str, Module | Function]
    numbers: dict[str, bool | int | float]
    namespace: dict[str, Any]
    unit: Any

    def where(self, node: ast.AST) -> str:
        raise NotImplementedError

    def hoist(self, text: str, kind: Scalar | Tuple) -> str:
        raise NotImplementedError

    def refuse(self, node: ast.AST, why: str) -> Untranslatable:
        construct = ast.unparse(node)
        if len(construct) > 60:
            construct = construct[:57] + "..."
        return Untranslatable(
            f"`{construct}` at {self.where(node)} cannot be translated to C: {why}"
        )

    # --- names and values --------------------------------------------------

    def value_of(self, node: ast.expr) -> tuple[str, Type]:
        """C text and type of an expression."""
        method = getattr(self, "_" + type(node).__name__, None)
        if method is None:
            raise self.refuse(node, f"no C for a Python {type(node).__name__} expression")
        return method(node)

    def scalar(self, node: ast.expr) -> tuple[str, Scalar]:
        text, kind = self.value_of(node)
        if not isinstance(kind, Scalar):
            raise self.refuse(node, "a number is needed here, not a tuple or a module")
        return text, kind

    def simple(self, node: ast.expr) -> tuple[str, Type]:
        """An operand C may read twice: a name, a constant, or a temporary."""
        text, kind = self.value_of(node)
        if isinstance(kind, Module | Function | Table | Rows) or isinstance(
            node, ast.Name | ast.Constant
        ):
            return text, kind
        return self.hoist(text, kind), kind

    def global_value(self, name: str, node: ast.AST) -> Any:
        if name in self.namespace:
            return self.namespace[name]
        if hasattr(builtins, name):
            raise self.refuse(
                node, f"the builtin {name} is only callable here (abs, float, int, min, max, len)"
            )
        raise self.refuse(node, f"{name} is not defined")

    def outside(self, value: Any, name: str, node: ast.AST) -> tuple[str, Type]:
        """A value from outside the function: a module, one of the model's
        functions (an argument bound at translation time), or a module constant."""
        if isinstance(value, type(math)):
            return name, Module(value)
        if isinstance(value, types.FunctionType):
            return name, Function(value)
        if isinstance(value, bool | int | float):
            return self.unit.constant(name, value, self.where(node)), literal(
                value, self.where(node)
            )[1]
        rows = rows_of(value, self.where(node)) if type(value) is tuple else None
        if rows:
            return self.unit.rows(name, *rows), rows[1]
        table = table_of(value, self.where(node)) if type(value) is tuple else None
        if table:
            return self.unit.table(name, *table), table[1]
        raise self.refuse(
            node, f"{name} is a {type(value).__name__}; C takes numbers, tuples and calls"
        )

    def _Name(self, node: ast.Name) -> tuple[str, Type]:
        if node.id in self.unrolled:  # an unrolled loop's variable (`unrolled`)
            return f"INT64_C({self.unrolled[node.id]})", INT
        if node.id in self.locals:
            return self.c_names.get(node.id, node.id + "_"), self.locals[node.id]
        if node.id in self.bound:
            return node.id, self.bound[node.id]
        if node.id in self.numbers:
            return self.outside(self.numbers[node.id], node.id, node)
        return self.outside(self.global_value(node.id, node), node.id, node)

    def _Constant(self, node: ast.Constant) -> tuple[str, Type]:
        return literal(node.value, self.where(node))

    def _Attribute(self, node: ast.Attribute) -> tuple[str, Type]:
        text, owner = self.value_of(node.value)
        if isinstance(owner, Tuple) and owner.names and node.attr in owner.names:
            return self.items_of(node.value, text, owner)[
                owner.names.index(node.attr)
            ], owner.items[owner.names.index(node.attr)]
        if not isinstance(owner, Module):
            raise self.refuse(
                node, "attributes are read from modules and NamedTuples only (no objects in C)"
            )
        if owner.module is math:
            if node.attr not in MATH_CONSTANTS:
                raise self.refuse(node, f"math.{node.attr} is not a constant C has")
            return literal(getattr(math, node.attr), self.where(node))
        value = getattr(owner.module, node.attr, None)
        return self.outside(value, node.attr, node)

    # --- arithmetic ----------------------------------------------------------

    def _BinOp(self, node: ast.BinOp) -> tuple[str, Type]:
        left, left_type = self.value_of(node.left)
        if isinstance(node.op, ast.Add) and isinstance(left_type, Tuple):
            first = self.items_of(node.left, left, left_type)
            second, second_type = self.fields(node.right)
            return self.built(first + second, left_type.items + second_type.items)
        if not isinstance(left_type, Scalar):
            raise self.refuse(node.left, "a number is needed here, not a tuple or a module")
        right, right_type = self.scalar(node.right)
        op = type(node.op)
        if op in BINARY:
            kind = FLOAT if op is ast.Div else arithmetic(left_type, right_type)
            if op is ast.Div and left_type is not FLOAT and right_type is not FLOAT:
                left = f"(double){left}"  # Python's true division of two counts
            return parenthesized(f"{left} {BINARY[op]} {right}"), kind
        if op in BITWISE and FLOAT not in (left_type, right_type):
            return parenthesized(f"{left} {BITWISE[op]} {right}"), INT
        if op is ast.Pow and FLOAT in (left_type, right_type):
            return f"pow({left}, {right})", FLOAT
        raise self.refuse(node, f"no C for {type(node.op).__name__} on {left_type.python} "
                          f"and {right_type.python} with Python's result")  # fmt: skip

    def _UnaryOp(self, node: ast.UnaryOp) -> tuple[str, Type]:
        text, kind = self.scalar(node.operand)
        if isinstance(node.op, ast.USub):
            return f"(-{text})", kind
        if isinstance(node.op, ast.UAdd):
            return text, kind
        if isinstance(node.op, ast.Not):
            return f"(!{self.truth(node.operand)})", BOOL
        if isinstance(node.op, ast.Invert) and kind is INT:
            return f"(~{text})", INT
        raise self.refuse(node, f"no C for {type(node.op).__name__} on a {kind.python}")

    def truth(self, node: ast.expr) -> str:
        """A condition: a bool (a number's truth would hide a mistaken operand)."""
        text, kind = self.scalar(node)
        if kind is not BOOL:
            raise self.refuse(node, f"a condition must be a bool, not a {kind.python}")
        return text

    def _BoolOp(self, node: ast.BoolOp) -> tuple[str, Type]:
        joiner = " && " if isinstance(node.op, ast.And) else " || "
        return "(" + joiner.join(self.truth(value) for value in node.values) + ")", BOOL

    def _Compare(self, node: ast.Compare) -> tuple[str, Type]:
        operands = [node.left, *node.comparators]
        texts = []
        for k, operand in enumerate(operands):
            # A chain's inner operand is evaluated once in Python.
            text, kind = (self.simple if 0 < k < len(operands) - 1 else self.value_of)(operand)
            if not isinstance(kind, Scalar):
                raise self.refuse(operand, "only numbers are compared")
            texts.append(text)
        parts = []
        for k, op in enumerate(node.ops):
            if type(op) not in COMPARE:
                raise self.refuse(node, f"no C for the comparison {type(op).__name__}")
            parts.append(f"({texts[k]} {COMPARE[type(op)]} {texts[k + 1]})")
        return ("(" + " && ".join(parts) + ")" if len(parts) > 1 else parts[0]), BOOL

    def _IfExp(self, node: ast.IfExp) -> tuple[str, Type]:
        test = self.truth(node.test)
        body, body_type = self.value_of(node.body)
        other, other_type = self.value_of(node.orelse)
        if body_type != other_type or body_type == Tuple(()):
            raise self.refuse(
                node, f"both branches must have one type ({body_type} and {other_type})"
            )
        return f"({test} ? {body} : {other})", body_type

    # --- tuples --------------------------------------------------------------

    def fields(self, node: ast.expr) -> tuple[list[str], Tuple]:
        """A tuple-valued expression's items as C texts, the tuple read once."""
        text, kind = self.value_of(node)
        if not isinstance(kind, Tuple):
            raise self.refuse(node, "a tuple is needed here")
        return self.items_of(node, text, kind), kind

    def items_of(self, node: ast.expr, text: str, kind: Tuple) -> list[str]:
        if not kind.items:  # the empty tuple a tuple is built from
            return []
        if not isinstance(node, ast.Name):
            text = self.hoist(text, kind)
        return [f"{text}.v{k}" for k in range(len(kind.items))]

    def built(self, texts: list[str], kinds: tuple[Scalar, ...]) -> tuple[str, Type]:
        kind = Tuple(kinds)
        if not kinds:  # no C value: only a start for `+` (`functions.assign`)
            return "", kind
        self.unit.struct(kind)
        return f"(({kind.c}){{{', '.join(texts)}}})", kind
