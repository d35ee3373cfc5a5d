"""Tuple displays and subscripts: a tuple's items by constant index or slice,
a constant table's item by an int, a table of rows' item by two ints."""

import ast
from collections.abc import Callable

from .expressions import Expressions
from .types import INT, Rows, Scalar, Table, Type, Untranslatable


class Subscripts(Expressions):
    """Mixed into `calls.Calls`, below `functions.FunctionTranslator`."""

    constant_int: Callable[[ast.expr], int | None]  # `unrolled.Unrolled`'s

    def _Tuple(self, node: ast.Tuple) -> tuple[str, Type]:
        items: list[tuple[str, Scalar]] = []
        for element in node.elts:
            if isinstance(element, ast.Starred):  # (*pair, x): the tuple's items
                texts, spread = self.fields(element.value)
                items += zip(texts, spread.items, strict=True)
            else:
                items.append(self.scalar(element))
        return self.built([text for text, _ in items], tuple(kind for _, kind in items))

    def _Subscript(self, node: ast.Subscript) -> tuple[str, Type]:
        if isinstance(node.value, ast.Subscript) and isinstance(
            node.value.value, ast.Name | ast.Attribute
        ):
            text, rows = self.value_of(node.value.value)
            if isinstance(rows, Rows):
                return self.row_entry(node, text, rows)
        if isinstance(node.value, ast.Name | ast.Attribute):
            text, table = self.value_of(node.value)
            if isinstance(table, Table):
                return self.entry(node, text, table)
            if isinstance(table, Rows):
                raise self.refuse(node, "a table of rows is read an item at a time: T[row][k]")
        items, kind = self.fields(node.value)
        n = len(items)
        bound = node.slice
        if isinstance(bound, ast.Slice):
            if bound.step is not None:
                raise self.refuse(node, "a slice with a step")
            start, stop = (self.index(b, node) if b else None for b in (bound.lower, bound.upper))
            chosen = range(n)[slice(start, stop)]
            return self.built([items[k] for k in chosen], tuple(kind.items[k] for k in chosen))
        k = self.index(bound, node)
        if not -n <= k < n:
            raise self.refuse(node, f"index {k} is beyond the tuple's {n} items")
        return items[k], kind.items[k]

    def entry(self, node: ast.Subscript, name: str, table: Table) -> tuple[str, Type]:
        """A constant table's item: by a constant (checked here) or by an int, which
        the caller keeps in 0..size-1 (Python's negative indices are not C's)."""
        if isinstance(node.slice, ast.Slice):
            raise self.refuse(node, "a constant table is read an item at a time")
        try:
            k = self.index(node.slice, node)
        except Untranslatable:
            position, kind = self.scalar(node.slice)
            if kind is not INT:
                raise self.refuse(node, "a table's index is an int") from None
            return f"{name}[{position}]", table.item
        if not -table.size <= k < table.size:
            raise self.refuse(node, f"index {k} is beyond the table's {table.size} items")
        return f"{name}[{k % table.size}]", table.item

    def row_entry(self, node: ast.Subscript, name: str, rows: Rows) -> tuple[str, Type]:
        """`T[row][k]` of a tuple of tables: ints the caller keeps in range, as
        for a table's item."""
        assert isinstance(node.value, ast.Subscript)
        row, row_kind = self.scalar(node.value.slice)
        item, item_kind = self.scalar(node.slice)
        if row_kind is not INT or item_kind is not INT or isinstance(node.slice, ast.Slice):
            raise self.refuse(node, "a table of rows is indexed by two ints")
        return f"{name}[{self.unit.starts[name]}[{row}] + {item}]", rows.item

    def index(self, node: ast.expr, whole: ast.AST) -> int:
        """A constant index (C's struct fields are named, not computed): see
        `unrolled.Unrolled.constant_int`."""
        value = self.constant_int(node)
        if value is None:
            raise self.refuse(whole, "a tuple is indexed by an integer constant only")
        return value
