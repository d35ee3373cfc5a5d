"""Calls: the `math` functions C's library computes as CPython does, the
builtins abs, float, int, min and max, and calls between the model's own
functions (each translated once per binding of its module parameters)."""

import ast
import math
import types
from typing import Any

from .expressions import MATH_CALLS, MATH_REFUSED
from .tuples import Subscripts
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
    type_of_annotation,
)

BUILTINS = ("abs", "float", "int", "min", "max", "len")


def accepts(parameter: Scalar | Tuple, argument: Type) -> bool:
    """Whether C's implicit conversion gives the parameter Python's value."""
    if parameter == argument:
        return True
    return (parameter is FLOAT and argument in (INT, BOOL)) or (
        parameter is INT and argument is BOOL
    )


class Calls(Subscripts):
    def _Call(self, node: ast.Call) -> tuple[str, Type]:
        if any(k.arg is None for k in node.keywords):
            raise self.refuse(node, "no ** arguments in C")
        function = node.func
        target: Any = None
        if isinstance(function, ast.Name) and isinstance(self.bound.get(function.id), Function):
            target = self.bound[function.id].function  # type: ignore[union-attr]
        elif isinstance(function, ast.Name) and function.id not in self.locals | self.bound:
            if function.id not in self.namespace and function.id in BUILTINS:
                return self.builtin(node, function.id)
            target = self.global_value(function.id, node)
            if isinstance(target, type) and issubclass(target, tuple):
                return self.named_tuple(node, target)
        elif isinstance(function, ast.Attribute):
            _, owner = self.value_of(function.value)
            if isinstance(owner, Module) and owner.module is math:
                return self.math_call(node, function.attr)
            if isinstance(owner, Module):
                target = getattr(owner.module, function.attr, None)
        if any(isinstance(a, ast.Starred) for a in node.args):
            if not isinstance(target, types.FunctionType):
                raise self.refuse(node, "a tuple is spread (*) into the model's own functions only")
        if isinstance(target, types.FunctionType):
            return self.project_call(node, target)
        raise self.refuse(
            node, "only the model's own functions, math and abs/float/int/min/max are called in C"
        )

    def named_tuple(self, node: ast.Call, target: type) -> tuple[str, Type]:
        """A NamedTuple of numbers built from its items, given in order."""
        kind = type_of_annotation(target, self.where(node))
        if not isinstance(kind, Tuple) or node.keywords or len(node.args) != len(kind.items):
            raise self.refuse(node, f"a {target.__name__} is built from its items, in order")
        texts = []
        for argument, item in zip(node.args, kind.items, strict=True):
            text, given = self.scalar(argument)
            if not accepts(item, given):
                raise self.refuse(node, f"a {given} for a {item} field of {target.__name__}")
            texts.append(text)
        self.unit.struct(kind)
        return f"(({kind.c}){{{', '.join(texts)}}})", kind

    def math_call(self, node: ast.Call, name: str) -> tuple[str, Type]:
        if name not in MATH_CALLS:
            raise self.refuse(
                node, MATH_REFUSED.get(name, f"math.{name} has no C counterpart here")
            )
        count, result = MATH_CALLS[name]
        if node.keywords or len(node.args) != count:
            raise self.refuse(node, f"math.{name} takes {count} positional argument(s)")
        text = f"{name}({', '.join(self.scalar(a)[0] for a in node.args)})"
        # math.floor, ceil and trunc give Python ints.
        return (f"((int64_t){text})" if result is INT else text), result

    def builtin(self, node: ast.Call, name: str) -> tuple[str, Type]:
        if node.keywords or not node.args or (name not in ("min", "max") and len(node.args) != 1):
            raise self.refuse(node, f"{name}() with these arguments")
        if name in ("min", "max"):
            return self.extreme(node, name)
        if name == "len":
            _, sized = self.value_of(node.args[0])
            if isinstance(sized, Table | Tuple | Rows):
                size = (
                    sized.size
                    if isinstance(sized, Table)
                    else len(sized.sizes)
                    if isinstance(sized, Rows)
                    else len(sized.items)
                )
                return f"INT64_C({size})", INT
            raise self.refuse(node, "len() of a tuple or a constant table")
        text, kind = self.scalar(node.args[0])
        if name == "float":
            return f"((double){text})", FLOAT
        if name == "int":
            return (f"((int64_t){text})" if kind is FLOAT else text), INT
        if kind is FLOAT:
            return f"fabs({text})", FLOAT
        value, _ = self.simple(node.args[0])
        return f"({value} < 0 ? -{value} : {value})", kind

    def extreme(self, node: ast.Call, name: str) -> tuple[str, Type]:
        """min/max as Python picks: the first item, replaced by each later one
        strictly smaller (larger); so a NaN wins only where Python's does."""
        if len(node.args) < 2:
            raise self.refuse(node, f"{name}() of one iterable")
        best, kind = self.simple(node.args[0])
        comparison = "<" if name == "min" else ">"
        for argument in node.args[1:]:
            other, other_kind = self.simple(argument)
            if other_kind != kind or not isinstance(kind, Scalar):
                raise self.refuse(node, f"{name}() of numbers of one type")
            best = self.hoist(f"({other} {comparison} {best} ? {other} : {best})", kind)
        return best, kind

    def project_call(self, node: ast.Call, function: types.FunctionType) -> tuple[str, Type]:
        names = self.unit.parameter_names(function, self.where(node))
        # A tuple spread into the arguments (`f(*inputs)`) gives its items in order.
        positional: list[Any] = []
        for argument in node.args:
            if isinstance(argument, ast.Starred):
                texts, spread = self.fields(argument.value)
                positional += list(zip(texts, spread.items, strict=True))
            else:
                positional.append(argument)
        if len(positional) > len(names):
            raise self.refuse(node, f"{function.__name__} takes {len(names)} arguments")
        given: dict[str, Any] = dict(zip(names, positional, strict=False))
        for keyword in node.keywords:
            name = keyword.arg or "**"
            if name not in names or name in given:
                raise self.refuse(node, f"argument {name} of {function.__name__}")
            given[name] = keyword.value
        defaults = dict(
            zip(names[len(names) - len(function.__defaults__ or ()) :], function.__defaults__ or ())
        )
        modules: dict[str, Any] = {}
        values: dict[str, tuple[str, Type]] = {}
        shapes: dict[str, Tuple] = {}
        for name in names:
            if name in given:
                value = given[name]
                text, kind = value if isinstance(value, tuple) else self.value_of(value)
            elif name in defaults:
                text, kind = self.outside(defaults[name], name, node)
            else:
                raise self.refuse(node, f"no value for {function.__name__}'s {name}")
            if isinstance(kind, Module):
                modules[name] = kind.module
            elif isinstance(kind, Function):
                modules[name] = kind.function
            elif kind == Tuple(()):
                raise self.refuse(node, "an empty tuple has no C value: it only starts a tuple")
            else:
                values[name] = text, kind
                if isinstance(kind, Tuple):
                    shapes[name] = kind
        callee = self.unit.function(function, modules, self.where(node), shapes)
        if callee.optional:
            raise self.refuse(
                node, f"{function.__name__} may return None: only the step itself may"
            )
        for name, kind in callee.parameters:
            if name not in values or not accepts(kind, values[name][1]):
                raise self.refuse(node, f"{function.__name__}'s {name} takes a {kind}")
        arguments = ", ".join(values[name][0] for name, _ in callee.parameters)
        return f"{callee.c_name}({arguments})", callee.returns
