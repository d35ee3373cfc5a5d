"""The cells and sections of a model page's variable tables (tools/model_pages.py
puts them together): numbers as the modelDescription writes them, units with
their display unit, ranges, and indexed rows (`joint_<k>_...`) said once."""

import os
import re

SHOWN = ("name", "causality", "unit", "display_unit", "start", "min", "max", "description")
INDEX = re.compile(r"(?:(?<=_)|^)(\d+)(?=_|$)")  # the index in `joint_2_life_rate`


def _number(value) -> str:
    return "" if value is None else f"{value:.6g}"


def _unit(v) -> str:
    return v.unit + (f" ({v.display_unit})" if v.display_unit else "")


def _range(v) -> str:
    low, high = _number(v.min), _number(v.max)
    return f"[{low}, {high}]" if (low or high) else ""


def _one_of(texts: list[str]) -> str:
    """`texts` said once: their common start and end (to a word) around each
    one's own middle, in order ("about the input pin / output pin")."""
    if len(set(texts)) == 1:
        return texts[0]
    head = os.path.commonprefix(texts)
    head = head[: head.rfind(" ") + 1]
    tail = os.path.commonprefix([t[len(head) :][::-1] for t in texts])[::-1]
    cut = re.search(r"[ ,;:]", tail)
    tail = tail[cut.start() :] if cut else ""
    middles = [t[len(head) : len(t) - len(tail)] for t in texts]
    return head + " / ".join(middles) + tail


def _index(v) -> str:
    found = INDEX.search(v.name)
    assert found, v.name
    return found.group(1)


def _indexed(variables) -> list[tuple[str, list]]:
    """The rows in table order, those that differ only by an index in their name
    (`joint_1_life_rate`, `joint_2_life_rate`) and in their text and start value
    under one name `joint_<k>_life_rate`: (shown name, rows)."""
    groups: dict[tuple, list] = {}
    for v in variables:
        key = (INDEX.sub("<k>", v.name, count=1), v.causality, _unit(v), v.min, v.max)
        groups.setdefault(key if INDEX.search(v.name) else (v.name,), []).append(v)
    shown = []
    for key, rows in groups.items():
        if len(rows) == 1:
            shown.append((f"`{rows[0].name}`", rows))
            continue
        name = f"`{key[0]}`, k = {', '.join(_index(v) for v in rows)}"
        shown.append((name, rows))
    return shown


def _description(rows) -> str:
    if len(rows) == 1:
        return rows[0].description
    pattern = r"(?<![\w.]){}(?![\w.])"
    general = {re.sub(pattern.format(_index(v)), "k", v.description, count=1) for v in rows}
    return general.pop() if len(general) == 1 else _one_of([v.description for v in rows])


def _section(rows_by_name) -> list[str]:
    """One causality's table, without the columns it leaves empty."""
    columns = {
        "name": lambda name, rows: name,
        "unit (display)": lambda name, rows: _unit(rows[0]),
        "start": lambda name, rows: _one_of([_number(v.start) for v in rows]),
        "range": lambda name, rows: _range(rows[0]),
        "description": lambda name, rows: _description(rows),
    }
    cells = [
        [cell(*entry).replace("|", "\\|") for cell in columns.values()] for entry in rows_by_name
    ]
    kept = [i for i in range(len(columns)) if any(row[i] for row in cells)]
    heads = list(columns)
    lines = ["| " + " | ".join(heads[i] for i in kept) + " |", "|" + "---|" * len(kept)]
    lines += ["| " + " | ".join(row[i] for i in kept) + " |" for row in cells]
    return lines


def _shown(v) -> tuple:
    return tuple(getattr(v, attribute) for attribute in SHOWN)
