"""The results file: one summary table whose rows are keyed by their first cell
(section number and what is measured, never a measured figure), then the
sections' own tables under `## ` headings.

A full run writes the whole file. A run of some sections, or of some models,
replaces the rows it measured (same key), adds the ones the file lacks in
section order, replaces its sections' own tables, and says so under the
summary table; every other line stays as the full run wrote it.
"""

import re

TABLE_HEAD = ("| benchmark | result | goal | met |", "|---|---|---|---|")
ALONE = "Re-measured alone"


def key(row: str) -> str:
    """A summary row's first cell."""
    return row.split(" | ", 1)[0]


def section(row: str) -> int:
    """A summary row's section number (an older file's "7a." counts as 7)."""
    found = re.match(r"\| (\d+)", row)
    return int(found.group(1)) if found else 0


def full(header: str, rows: list[str], footnote: str, blocks: dict[str, str]) -> str:
    """The whole file: `blocks` maps a `## ` heading to the text under it."""
    parts = [header, "", *TABLE_HEAD, *rows, "", footnote, ""]
    for heading, text in blocks.items():
        parts += [f"## {heading}", "", text, ""]
    return "\n".join(parts)


def merged(text: str, rows: list[str], blocks: dict[str, str], note: str) -> str:
    """`text` with `rows` and `blocks` replacing theirs, and `note` (the partial
    run's command) under the summary table, replacing a note of the same command."""
    lines = text.splitlines()
    start = lines.index(TABLE_HEAD[1]) + 1
    end = start
    while end < len(lines) and lines[end].startswith("| "):
        end += 1
    summary = lines[start:end]
    new = {key(row): row for row in rows}
    kept = [new.pop(key(row), row) for row in summary]
    for row in new.values():  # rows the file lacks: after the last of their section or before
        at = max((i + 1 for i, old in enumerate(kept) if section(old) <= section(row)), default=0)
        kept.insert(at, row)
    after = lines[end:]
    command = note.split("`")[1] if "`" in note else note
    notes = [i for i, line in enumerate(after) if line.startswith(ALONE) and f"`{command}`" in line]
    for i in reversed(notes):  # with the blank line that follows it
        del after[i : i + 2]
    after = ["", note, *after] if after[:1] == [""] else ["", note, "", *after]
    out = "\n".join([*lines[:start], *kept, *after])
    for heading, block in blocks.items():
        out = with_block(out, heading, block)
    return out.rstrip("\n") + "\n"


def with_block(text: str, heading: str, block: str) -> str:
    """`text` with the part under `## heading` replaced by `block` (added at the end
    when the file has none)."""
    lines = text.rstrip("\n").splitlines()
    title = f"## {heading}"
    if title not in lines:
        return "\n".join([*lines, "", title, "", block]) + "\n"
    start = lines.index(title)
    end = next((i for i in range(start + 1, len(lines)) if lines[i].startswith("## ")), len(lines))
    tail = ["", *lines[end:]] if end < len(lines) else []
    return "\n".join([*lines[:start], title, "", block, *tail]) + "\n"
