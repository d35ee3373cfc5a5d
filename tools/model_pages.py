"""Regenerate what the docs say about the models from the models themselves.

Each generated block sits between `<!-- key:begin -->` and `<!-- key:end -->`:
- `models` in README.md: the index of every model discovery
  finds (its page, FMI versions and description, from its spec);
- `variables` on each model's page (models/<name>/README.md): its variable table;
- `fmi3-arrays` on the page of a model with FMI 3 arrays: the arrays' table.

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
from cardan_joint.variable_schema import array_table

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
    table = spec.table()
    blocks = {"variables": table.markdown_table()}
    arrays = array_table(table.fmi3_variables())
    if arrays:
        blocks["fmi3-arrays"] = arrays
    return blocks


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
