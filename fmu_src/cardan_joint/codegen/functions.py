"""One Python function as one C function: its parameters and locals typed
(annotations, else float or the tuple its caller passes; a local takes the
type of its first value), its
statements in order, temporaries for values Python evaluates once."""

import ast
import inspect
import textwrap
import types
from dataclasses import dataclass, field
from typing import Any

from .calls import Calls, accepts
from .types import (
    FLOAT,
    Function,
    Module,
    Scalar,
    Tuple,
    Untranslatable,
    type_of_annotation,
)
from .unrolled import Unrolled


@dataclass
class Signature:
    c_name: str
    parameters: list[tuple[str, Scalar | Tuple]]
    returns: Any = None  # Scalar | Tuple once known
    optional: bool = False  # the function may return None (the step refused)
    text: list[str] = field(default_factory=list)

    def prototype(self) -> str:
        parameters = [f"{kind.c} {name}_" for name, kind in self.parameters]
        if self.optional:
            parameters.append(f"{self.returns.c} *result_")
        returns = "int" if self.optional else self.returns.c
        # `inline` lifts GCC's -O2 limit for a function called from more than
        # one place: the life torque's parts (`crosspiece_motion`, the torque
        # at a node) then take no call, and the tuples they pass by value are
        # not copied through memory at every node (docs/codegen.md).
        return f"static inline {returns} {self.c_name}({', '.join(parameters) or 'void'})"


def source_of(function: types.FunctionType) -> tuple[ast.FunctionDef, str, int]:
    """The function's tree, its file and the line its tree's line 1 is."""
    try:
        lines, first = inspect.getsourcelines(function)
    except (OSError, TypeError) as error:
        raise Untranslatable(f"{function.__qualname__}: no source to translate ({error})") from None
    tree = ast.parse(textwrap.dedent("".join(lines))).body[0]
    assert isinstance(tree, ast.FunctionDef)
    return tree, inspect.getsourcefile(function) or "?", first


class FunctionTranslator(Unrolled, Calls):
    def __init__(
        self,
        unit: Any,
        function: types.FunctionType,
        modules: dict,
        c_name: str,
        shapes: dict | None = None,
    ) -> None:
        self.unit = unit
        self.tree, self.file, self.first = source_of(function)
        self.namespace = function.__globals__
        self.bound: dict[str, Module | Function] = {
            name: Function(value) if isinstance(value, types.FunctionType) else Module(value)
            for name, value in modules.items()
            if not isinstance(value, bool | int | float)
        }
        # A number bound to a parameter (a step entry's limit) is a constant.
        self.numbers = {n: v for n, v in modules.items() if isinstance(v, bool | int | float)}
        self.locals: dict[str, Scalar | Tuple] = {}
        # The C variable of each local (a tuple rebound to another shape gets a
        # new one) and the type each C variable is declared with.
        self.c_names: dict[str, str] = {}
        self.declared: dict[str, Scalar | Tuple] = {}
        self.unrolled: dict[str, int] = {}
        self.unrolling: set[str] = set()
        self.loops: list[bool] = []
        self.branching = 0  # inside an if, a while or a loop C keeps
        self.temporaries: list[tuple[str, Scalar | Tuple]] = []
        self.pending: list[str] = []
        self.body: list[str] = []
        if function.__code__.co_freevars:
            raise self.refuse(self.tree, "a closure's variables have no C")
        arguments = self.tree.args
        if arguments.vararg or arguments.kwarg or arguments.kwonlyargs:
            raise self.refuse(self.tree, "C takes positional parameters only")
        parameters = []
        for argument in arguments.posonlyargs + arguments.args:
            if argument.arg in modules:
                continue
            if argument.annotation:
                kind = self.annotated(argument.annotation, argument)
            else:
                kind = (shapes or {}).get(argument.arg, FLOAT)
            self.locals[argument.arg] = kind
            parameters.append((argument.arg, kind))
        self.signature = Signature(c_name, parameters)
        self.returns_annotated(self.tree.returns)

    def where(self, node: ast.AST) -> str:
        return f"{self.file}:{self.first + getattr(node, 'lineno', 1) - 1}"

    def annotated(self, annotation: ast.expr, node: ast.AST) -> Scalar | Tuple:
        try:
            value = eval(compile(ast.Expression(annotation), self.file, "eval"), self.namespace)
        except Exception as error:
            raise self.refuse(annotation, f"its annotation does not evaluate ({error})") from None
        return type_of_annotation(value, self.where(node))

    def returns_annotated(self, annotation: ast.expr | None) -> None:
        """The return type, or None to take it from the first return; `X | None`:
        the function may refuse (the step itself only)."""
        if isinstance(annotation, ast.BinOp) and isinstance(annotation.op, ast.BitOr):
            if isinstance(annotation.right, ast.Constant) and annotation.right.value is None:
                self.signature.optional = True
                annotation = annotation.left
        inferred = annotation is None or (
            ast.unparse(annotation) == "tuple"
            or (isinstance(annotation, ast.Subscript) and "..." in ast.unparse(annotation.slice))
        )
        if not inferred:
            assert annotation is not None
            self.signature.returns = self.annotated(annotation, annotation)

    def hoist(self, text: str, kind: Scalar | Tuple) -> str:
        name = f"tmp_{len(self.temporaries)}"
        self.temporaries.append((name, kind))
        self.pending.append(f"{name} = {text};")
        return name

    # --- statements ---------------------------------------------------------

    def translate(self) -> Signature:
        self.block(self.tree.body, 1)
        if self.signature.returns is None:
            raise self.refuse(self.tree, "it returns no value")
        declarations = [f"    {kind.c} {name};" for name, kind in self.declared.items()]
        declarations += [f"    {kind.c} {name};" for name, kind in self.temporaries]
        self.signature.text = [self.signature.prototype(), "{", *declarations, *self.body, "}"]
        return self.signature

    def block(self, statements: list[ast.stmt], depth: int) -> None:
        for statement in statements:
            if isinstance(statement, ast.Expr) and isinstance(statement.value, ast.Constant):
                continue  # a docstring
            method = getattr(self, "_" + type(statement).__name__, None)
            if method is None:
                raise self.refuse(
                    statement, f"no C for a Python {type(statement).__name__} statement"
                )
            self.pending = []
            lines = method(statement, depth)
            pad = "    " * depth
            self.body += [pad + line for line in self.pending] + [line for line in lines if line]

    def nested(self, statements: list[ast.stmt], depth: int, straight: bool = False) -> list[str]:
        """The statements' C; not `straight`: a branch's or a kept loop's body."""
        outer, pending, self.body = self.body, self.pending, []
        self.branching += not straight
        self.block(statements, depth)
        self.branching -= not straight
        inner, self.body, self.pending = self.body, outer, pending
        return inner

    def assign(self, name: str, text: str, kind: Any, node: ast.AST) -> str:
        """`name = text`; "" for an empty tuple, which C does not hold."""
        if not isinstance(kind, Scalar | Tuple):
            raise self.refuse(node, f"{name} would hold {kind}: C keeps numbers and tuples")
        if name in self.unrolling:
            raise self.refuse(node, f"{name} is an unrolled loop's constant")
        self.unrolled.pop(name, None)
        known = self.locals.setdefault(name, kind)
        if name not in self.c_names:
            self.c_names[name] = f"{name}_"
            if name not in dict(self.signature.parameters):
                self.declared[f"{name}_"] = kind
        if known != kind:
            # A tuple built item by item takes a new shape each time: a new C
            # variable, where no branch or kept loop needs one type at its end.
            if not (isinstance(known, Tuple) and isinstance(kind, Tuple) and not self.branching):
                raise self.refuse(
                    node, f"{name} holds {known} values, not {kind}: C keeps one type per name"
                )
            self.c_names[name] = f"{name}__{len(self.declared)}"
            self.declared[self.c_names[name]] = kind
            self.locals[name] = kind
        if isinstance(kind, Tuple) and not kind.items:
            self.declared.pop(self.c_names[name], None)
            return ""
        return f"{self.c_names[name]} = {text};"

    def _Assign(self, node: ast.Assign, depth: int) -> list[str]:
        pad = "    " * depth
        if len(node.targets) != 1:
            raise self.refuse(node, "one target per assignment")
        target = node.targets[0]
        if isinstance(target, ast.Name):
            text, kind = self.value_of(node.value)
            return [pad + self.assign(target.id, text, kind, node)]
        if not isinstance(target, ast.Tuple) or not all(
            isinstance(t, ast.Name) for t in target.elts
        ):
            raise self.refuse(node, "targets are names or a tuple of names")
        names = [t.id for t in target.elts]  # type: ignore[attr-defined]
        if isinstance(node.value, ast.Tuple) and len(node.value.elts) == len(names):
            # Every value first, as Python's a, b = b, a.
            items = [self.scalar(element) for element in node.value.elts]
            values = [(self.hoist(text, kind), kind) for text, kind in items]
        else:
            texts, whole = self.fields(node.value)
            if len(texts) != len(names):
                raise self.refuse(node, f"{len(names)} names for a tuple of {len(texts)}")
            values = list(zip(texts, whole.items, strict=True))
        return [pad + self.assign(n, t, k, node) for n, (t, k) in zip(names, values, strict=True)]

    def _AnnAssign(self, node: ast.AnnAssign, depth: int) -> list[str]:
        if node.value is None or not isinstance(node.target, ast.Name):
            raise self.refuse(node, "an annotated assignment gives a name a value")
        kind = self.annotated(node.annotation, node)
        text, given = self.value_of(node.value)
        if not accepts(kind, given):
            raise self.refuse(node, f"a {given} value for a {kind} name")
        return ["    " * depth + self.assign(node.target.id, text, kind, node)]

    def _AugAssign(self, node: ast.AugAssign, depth: int) -> list[str]:
        if not isinstance(node.target, ast.Name):
            raise self.refuse(node, "only a name is updated in place")
        value = ast.BinOp(ast.Name(id=node.target.id), node.op, node.value)
        text, kind = self.value_of(ast.copy_location(value, node))
        return ["    " * depth + self.assign(node.target.id, text, kind, node)]

    def _If(self, node: ast.If, depth: int) -> list[str]:
        pad = "    " * depth
        lines = [f"{pad}if ({self.truth(node.test)}) {{", *self.nested(node.body, depth + 1)]
        if node.orelse:
            # An elif's test is evaluated only once the if's has failed.
            lines += [f"{pad}}} else {{", *self.nested(node.orelse, depth + 1)]
        return lines + [f"{pad}}}"]

    def _While(self, node: ast.While, depth: int) -> list[str]:
        pad = "    " * depth
        if node.orelse:
            raise self.refuse(node, "a while loop's else")
        test = self.truth(node.test)
        before, self.pending = self.pending, []
        inner = "    " * (depth + 1)
        head = [f"{pad}for (;;) {{", *(inner + line for line in before), f"{inner}if (!{test})",
                f"{inner}    break;"]  # fmt: skip
        self.loops.append(False)
        body = self.nested(node.body, depth + 1)
        self.loops.pop()
        return head + body + [f"{pad}}}"]

    def _Return(self, node: ast.Return, depth: int) -> list[str]:
        pad = "    " * depth
        signature = self.signature
        if node.value is None or (
            isinstance(node.value, ast.Constant) and node.value.value is None
        ):
            if not signature.optional:
                raise self.refuse(
                    node, "a return of None from a function not annotated `... | None`"
                )
            return [f"{pad}return 0;"]
        text, kind = self.value_of(node.value)
        if kind == Tuple(()):
            raise self.refuse(node, "an empty tuple has no C value: it only starts a tuple")
        if signature.returns is None and isinstance(kind, Scalar | Tuple):
            signature.returns = kind
        if not accepts(signature.returns, kind):
            raise self.refuse(node, f"returns a {kind} where it returns a {signature.returns}")
        if signature.optional:
            return [f"{pad}*result_ = {text};", f"{pad}return 1;"]
        return [f"{pad}return {text};"]

    def _Break(self, node: ast.Break, depth: int) -> list[str]:
        self.leaves_loop(node)
        return ["    " * depth + "break;"]

    def _Continue(self, node: ast.Continue, depth: int) -> list[str]:
        self.leaves_loop(node)
        return ["    " * depth + "continue;"]

    def _Pass(self, node: ast.Pass, depth: int) -> list[str]:
        return []
