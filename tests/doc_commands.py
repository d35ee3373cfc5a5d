"""The shell commands of the README and the docs, as a reader copies them: the
lines of indented or sh/bash/console code blocks whose first word is a program
(equations and layouts in code blocks are not commands)."""

import re
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
PROGRAMS = ("python", "python3", "pip", "pytest", "cardan-joint", "fmpy", "dask", "ruff", "mypy")
# Shell commands a page may use to prepare a run (not tools of the venv).
SHELL = ("printf", "env")
SHELL_FENCES = ("", "sh", "bash", "console", "shell")


def pages() -> list:
    """The README, the docs and the model folders' readmes."""
    models = sorted((ROOT / "fmu_src" / "cardan_joint" / "models").glob("*/README.md"))
    return [ROOT / "README.md", *sorted((ROOT / "docs").rglob("*.md")), *models]


def _program(line: str) -> str:
    """The program a command line starts (after `env -i NAME=value ...`), as written."""
    words = [w for w in line.split() if not re.fullmatch(r"-i|[A-Z_]+=\S*", w)]
    return words[1] if words[:1] == ["env"] and len(words) > 1 else (words or [""])[0]


def commands(page: Path) -> list:
    """(line number, command) of every shell command on `page`, in order."""
    found, fence = [], None
    for number, line in enumerate(page.read_text().splitlines(), 1):
        text = line.strip()
        if text.startswith("```"):
            fence = None if fence is not None else text[3:].strip()
            continue
        in_block = fence in SHELL_FENCES if fence is not None else line.startswith("    ")
        if not (in_block and text):
            continue
        program = _program(text)
        if program.startswith((".venv/bin/", "/tmp/")) or Path(program).name in PROGRAMS:
            found.append((number, text))
        elif program in SHELL:
            found.append((number, text))
    return found


def venv_program(command: str) -> bool:
    """Whether the command calls its tool the one way the docs call tools: the
    venv's own (`.venv/bin/...`), except the `python3 -m venv` that makes it."""
    program = _program(command)
    return (
        program.startswith((".venv/bin/", "/tmp/"))
        or program in SHELL
        or command.startswith("python3 -m venv .venv")
    )


def inline_commands(page: Path) -> list:
    """(line number, span) of the `code spans` in prose that start a program."""
    found = []
    for number, line in enumerate(page.read_text().splitlines(), 1):
        for span in re.findall(r"`([^`\n]+)`", line):
            program = _program(span)
            if program.startswith(".venv/bin/") or Path(program).name in PROGRAMS:
                found.append((number, span))
    return found


def unlike_the_rest(page: Path) -> list:
    """ "<page>:<line>: <command>" for each command in a block, or each `python`,
    `pip` or `cardan-joint` command in prose, not called as `.venv/bin/...`."""
    spans = [(n, s) for n, s in inline_commands(page) if len(s.split()) > 1]
    spans = [
        (n, s) for n, s in spans if Path(_program(s)).name in ("python", "pip", "cardan-joint")
    ]
    return [
        f"{page.relative_to(ROOT)}:{number}: {command}"
        for number, command in commands(page) + spans
        if not venv_program(command)
    ]
