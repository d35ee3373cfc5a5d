"""`for` loops: over `range(...)` a C loop; over a tuple's positions
(`for k in range(len(t))`: bounds that are ints known at translation time,
one of them the length of a tuple) unrolled, one copy of the body per k, k a
constant in each, so `t[k]` and `t[3 * k + 1]` read a struct's fields and a
tuple may grow by an item a copy (`speeds = speeds + (w,)`). A propshaft's
joints are such a loop."""

import ast
import operator
from collections.abc import Callable
from typing import Any

from .types import INT, Rows, Table, Tuple, Untranslatable

# The int operations a constant index or bound may use, as Python computes them.
_CONSTANT_OPERATIONS = {
    ast.Add: operator.add,
    ast.Sub: operator.sub,
    ast.Mult: operator.mul,
    ast.FloorDiv: operator.floordiv,
}
# More copies than any tuple the models pass: a longer loop is not unrolled.
MAX_UNROLLED = 64


class Unrolled:
    """Mixed into `functions.FunctionTranslator`, which provides the scope."""

    locals: dict
    bound: dict
    namespace: dict
    # An unrolled loop's variable -> its value in the copy being translated (and,
    # after the loop, its last value, as Python leaves it).
    unrolled: dict[str, int]
    # Per enclosing loop, whether it is unrolled (no break or continue there).
    loops: list[bool]
    unrolling: set[str]  # the variables of the unrolled loops being translated

    # The translator's (annotations only: this class comes first in its bases).
    refuse: Callable[[ast.AST, str], Untranslatable]
    value_of: Callable[[ast.expr], Any]
    nested: Callable[..., list[str]]
    scalar: Callable[[ast.expr], Any]
    hoist: Callable[[str, Any], str]
    assign: Callable[[str, str, Any, ast.AST], str]
    index: Callable[[ast.expr, ast.AST], int]

    def _For(self, node: ast.For, depth: int) -> list[str]:
        pad = "    " * depth
        call = node.iter
        if (
            node.orelse
            or not isinstance(node.target, ast.Name)
            or not (
                isinstance(call, ast.Call)
                and isinstance(call.func, ast.Name)
                and call.func.id == "range"
            )
            or call.keywords
            or not 1 <= len(call.args) <= 3
        ):
            raise self.refuse(node, "a for loop runs over range(...) with a name, no else")
        if self.over_a_tuple(call.args):
            return self.unrolled_for(node, call.args, depth)
        bounds = [self.scalar(a) for a in call.args]
        if any(kind is not INT for _, kind in bounds):
            raise self.refuse(node, "range() takes ints")
        step = self.index(call.args[2], node) if len(call.args) == 3 else 1
        if step == 0:
            raise self.refuse(node, "range() with a step of 0")
        start = bounds[0][0] if len(bounds) > 1 else "0"
        stop = self.hoist(bounds[-1 if len(bounds) == 1 else 1][0], INT)
        self.assign(node.target.id, start, INT, node)  # the loop variable is a count
        name = node.target.id + "_"
        test = "<" if step > 0 else ">"
        head = f"{pad}for ({name} = {start}; {name} {test} {stop}; {name} += {step}) {{"
        self.loops.append(False)
        body = self.nested(node.body, depth + 1)
        self.loops.pop()
        return [head, *body, f"{pad}}}"]

    def constant_int(self, node: ast.expr) -> int | None:
        """The value of an int known at translation time: a literal, a module
        constant, an unrolled loop's variable, `len()` of a tuple or table, and
        + - * // of those (computed by Python); None for anything else."""
        if isinstance(node, ast.Constant):
            return node.value if type(node.value) is int else None
        if isinstance(node, ast.UnaryOp) and isinstance(node.op, ast.USub):
            value = self.constant_int(node.operand)
            return None if value is None else -value
        if isinstance(node, ast.Name):
            if node.id in self.unrolled:
                return self.unrolled[node.id]
            value = self.namespace.get(node.id)
            if node.id in self.locals or node.id in self.bound or type(value) is not int:
                return None
            return value
        if isinstance(node, ast.BinOp) and type(node.op) in _CONSTANT_OPERATIONS:
            left, right = self.constant_int(node.left), self.constant_int(node.right)
            if left is None or right is None or (isinstance(node.op, ast.FloorDiv) and not right):
                return None
            return _CONSTANT_OPERATIONS[type(node.op)](left, right)
        return self.length_of(node)[0]

    def length_of(self, node: ast.expr) -> tuple[int | None, bool]:
        """(len(x) if `node` is `len(x)` of a tuple or a constant table, else None;
        whether x is a tuple)."""
        if not (
            isinstance(node, ast.Call)
            and isinstance(node.func, ast.Name)
            and node.func.id == "len"
            and node.func.id not in self.locals
            and len(node.args) == 1
            and not node.keywords
            and isinstance(node.args[0], ast.Name | ast.Attribute)
        ):
            return None, False
        _, kind = self.value_of(node.args[0])
        if isinstance(kind, Tuple):
            return len(kind.items), True
        if isinstance(kind, Table):
            return kind.size, False
        if isinstance(kind, Rows):
            return len(kind.sizes), False
        return None, False

    def over_a_tuple(self, bounds: list[ast.expr]) -> bool:
        """Whether a range's bounds are all constants, one of them from a tuple's length."""
        if any(self.constant_int(bound) is None for bound in bounds):
            return False
        return any(
            self.length_of(inner)[1]
            for bound in bounds
            for inner in ast.walk(bound)
            if isinstance(inner, ast.expr)
        )

    def unrolled_for(self, node: ast.For, bounds: list[ast.expr], depth: int) -> list[str]:
        """One copy of the body for each value of the range, the variable a constant."""
        assert isinstance(node.target, ast.Name)
        name = node.target.id
        if name in self.locals:
            raise self.refuse(
                node, f"{name} is a variable already: an unrolled loop's is a constant"
            )
        values = range(*[self.constant_int(bound) or 0 for bound in bounds])
        if len(values) > MAX_UNROLLED:
            raise self.refuse(node, f"{len(values)} copies of a loop over a tuple's positions")
        pad = "    " * depth
        lines: list[str] = []
        self.loops.append(True)
        self.unrolling.add(name)
        for value in values:
            self.unrolled[name] = value
            lines += [f"{pad}/* {name} = {value} */", *self.nested(node.body, depth, straight=True)]
        self.unrolling.discard(name)
        self.loops.pop()
        if not values:
            self.unrolled.pop(name, None)
        return lines

    def leaves_loop(self, node: ast.stmt) -> None:
        """break and continue belong to a loop C keeps, not to an unrolled one."""
        if self.loops and self.loops[-1]:
            raise self.refuse(node, "no break or continue in a loop over a tuple's positions")
