"""Regenerate what the docs say about the models from the models themselves.

Each generated block sits between `<!-- key:begin -->` and `<!-- key:end -->`:
- `models` in README.md: the index of every model discovery
  finds (its page, FMI versions and description, from its spec);
- `variables` on each model's page (models/<name>/README.md): its variables, one table
  per causality, indexed rows (`joint_<k>_...`) once, rows the same as a base
  model's named with a link to its page (and the rest too, where another model
  adds the same rows to its own base), rows copied per joint from another
  model's table (`joint_<k>_life_rate`, "Joint k: ...") named in one line;
- `fmi3-arrays` on the page of a model with FMI 3 arrays: the arrays, one line.

    python tools/model_pages.py            # rewrite the stale blocks
    python tools/model_pages.py --check    # list them, exit 1 if any

tests/unit/test_model_pages.py fails while a block is stale, so a new model's
folder is listed and its page's tables are current without a hand edit here.
"""

from __future__ import annotations

import argparse
import os
import sys
from pathlib import Path

from cardan_joint.models import Model, discover

sys.path.insert(0, str(Path(__file__).resolve().parent))  # a script: its sibling module
from variable_tables import INDEX, SHOWN, _indexed, _section, _shown  # noqa: E402

ROOT = Path(__file__).resolve().parents[1]
INDEXES = (ROOT / "README.md",)


def model_index(page: Path) -> str:
    """The models' table, its links relative to `page`."""
    rows = ["| model | FMI | what |", "|---|---|---|"]
    for key, spec in sorted(discover().items()):
        link = Path(os.path.relpath(spec.page, page.parent)).as_posix()
        versions = ", ".join(f"{version}.0" for version in spec.fmi_versions)
        rows.append(f"| [{key}]({link}) | {versions} | {spec.description} |")
    return "\n".join(rows) + "\n"


def page_blocks(spec: Model) -> dict[str, str]:
    """The generated blocks of a model's page, by key."""
    base = bases().get(spec.key)
    blocks = {"variables": variables_block(spec, discover()[base] if base else None)}
    arrays = arrays_line(spec.table().fmi3_variables())
    if arrays:
        blocks["fmi3-arrays"] = arrays
    return blocks


# --- the variable tables -----------------------------------------------------


# What a page shows of a variable; two models' rows are "the same" when all of it is.
def bases() -> dict[str, str]:
    """Each model whose table is for the most part another's (a compliant drive's
    is its rigid drive's, with a spring) and that other model. Smaller tables go
    first, and a model that refers to another is no one's base."""
    tables = {key: spec.table() for key, spec in discover().items()}
    found: dict[str, str] = {}
    for key in sorted(tables, key=lambda k: (len(tables[k].VARIABLES), k)):
        own = {_shown(v) for v in tables[key].VARIABLES}
        shares = {
            other: len(own & {_shown(v) for v in tables[other].VARIABLES})
            for other in tables
            if other != key and other not in found and len(tables[other].VARIABLES) <= len(own)
        }
        best = max(shares, key=lambda other: (shares[other], other), default=None)
        if best and 2 * shares[best] >= len(own):
            found[key] = best
    return found


def _adding(spec: Model, base: Model, variables) -> Model | None:
    """The other model whose page shows as its own (beside its base's) exactly
    `variables`, the rows `spec` adds to its base (a compliant propshaft adds a
    compliant joint's spring), or None. That model's base is the smaller (so
    two such pages never point at each other)."""
    rows = {_shown(v) for v in variables}
    if not rows:
        return None
    models = discover()
    order = (len(base.table().VARIABLES), base.key)
    for key, base_key in bases().items():
        if key == spec.key or (len(models[base_key].table().VARIABLES), base_key) >= order:
            continue
        theirs = {_shown(v) for v in models[base_key].table().VARIABLES}
        own = {_shown(v) for v in models[key].table().VARIABLES} - theirs
        if own == rows:
            return models[key]
    return None


def variables_block(spec: Model, base: Model | None = None) -> str:
    """A model's variable tables, one per causality; the rows it shares with
    `base` are named, with a link to the page that shows them."""
    variables = spec.table().VARIABLES
    lines = []
    if base is not None:
        ours = {_shown(v) for v in variables}
        theirs = base.table().VARIABLES
        shown_there = {_shown(v) for v in theirs}
        variables = [v for v in variables if _shown(v) not in shown_there]
        link = Path(os.path.relpath(base.page, spec.page.parent)).as_posix()
        left = ", ".join(f"`{v.name}`" for v in theirs if _shown(v) not in ours)
        but = f", but {left}" if left else ""
        donor = _adding(spec, base, variables)
        if donor is not None:
            there = Path(os.path.relpath(donor.page, spec.page.parent)).as_posix()
            more, variables = f"; and those [{donor.key}]({there}) adds to its own base.", []
        else:
            more = "; and:" if variables else "."
        lines += [f"Every variable of [{base.key}]({link}) as it is there{but}{more}", ""]
    donor, copied = _copied(spec, variables) if base is None else (None, [])
    variables = [v for v in variables if v not in copied]
    for causality in ("input", "parameter", "output"):
        rows = [v for v in variables if v.causality == causality]
        if rows:
            lines += [f"{causality.capitalize()}s:", "", *_section(_indexed(rows)), ""]
    if donor is not None:
        there = Path(os.path.relpath(donor.page, spec.page.parent)).as_posix()
        shown = _indexed(copied)
        ks = {name.partition(", ")[2] for name, _ in shown} - {""}
        one = len(ks) == 1
        names = ", ".join(name.partition(", ")[0] if one else name for name, _ in shown)
        each = f" ({ks.pop()})" if one else ""
        lines += [
            f"And as on [{donor.key}]({there}), one parameter set for every joint,"
            f" the outputs for each joint k: {names}{each}.",
            "",
        ]
    return "\n".join(lines[:-1]) + "\n"


def _copy_of(v, o) -> bool:
    """Whether row `v` is row `o` of another table made per joint: the same but
    for an index prefix to its name (`joint_2_life_rate`) and a prefix to its
    description (`Joint 2: ...`, `Every joint: ...`)."""
    prefixed = v.name == o.name or INDEX.sub("<k>", v.name, count=1).endswith(f"<k>_{o.name}")
    same = all(getattr(v, a) == getattr(o, a) for a in SHOWN if a not in ("name", "description"))
    return prefixed and same and v.description.endswith(f": {o.description}")


def _copied(spec: Model, variables) -> tuple[Model | None, list]:
    """The model, shown in full on its own page, from which `spec` copies rows
    per joint (`_copy_of`), with the rows copied; (None, []) when fewer than 3."""
    found: tuple[Model | None, list] = (None, [])
    based = bases()
    for key, other in sorted(discover().items()):
        if key == spec.key or key in based:
            continue
        theirs = other.table().VARIABLES
        rows = [v for v in variables if any(_copy_of(v, o) for o in theirs)]
        if len(rows) >= 3 and len(rows) > len(found[1]):
            found = (other, rows)
    return found


def arrays_line(groups) -> str:
    """The FMI 3 arrays of a model (`groups`: its `fmi3_variables()`) in one line;
    empty if it has none."""
    arrays = [group for group in groups if len(group.rows) > 1]
    if not arrays:
        return ""
    each = [f"`{g.name}[{len(g.rows)}]` = `{g.rows[0].name}` … `{g.rows[-1].name}`" for g in arrays]
    return "FMI 3 arrays (elements in order): " + "; ".join(each) + ".\n"


def expected() -> dict[Path, dict[str, str]]:
    """Every generated block, by page and key."""
    pages = {page: {"models": model_index(page)} for page in INDEXES}
    for spec in discover().values():
        pages[spec.page] = page_blocks(spec)
    return pages


def _span(text: str, key: str, page: Path) -> tuple[int, int]:
    begin, end = f"<!-- {key}:begin -->\n", f"<!-- {key}:end -->"
    if text.count(begin) != 1 or text.count(end) != 1:
        raise ValueError(f"{page}: put one {begin.strip()} ... {end} where the {key} go")
    start = text.index(begin) + len(begin)
    return start, text.index(end, start)


def stale() -> list[str]:
    """The blocks that differ from what the code generates, as `page: key`."""
    found = []
    for page, blocks in expected().items():
        text = page.read_text() if page.is_file() else ""
        for key, block in blocks.items():
            try:
                start, stop = _span(text, key, page)
            except ValueError as error:
                found.append(str(error))
                continue
            if text[start:stop] != block:
                found.append(f"{page.relative_to(ROOT)}: {key}")
    return found


def rewrite() -> list[Path]:
    """Rewrite every stale block in place; the pages changed."""
    changed = []
    for page, blocks in expected().items():
        text = old = page.read_text()
        for key, block in blocks.items():
            start, stop = _span(text, key, page)
            text = text[:start] + block + text[stop:]
        if text != old:
            page.write_text(text)
            changed.append(page)
    return changed


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--check", action="store_true", help="list stale blocks, change nothing")
    args = parser.parse_args(argv)
    if args.check:
        found = stale()
        print("\n".join(found) or "every generated block is current")
        return 1 if found else 0
    for page in rewrite():
        print(f"rewrote {page.relative_to(ROOT)}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
