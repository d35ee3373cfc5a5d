"""No module of the package, the benchmarks, the examples, the tools or the tests
(C host included) is over 300 lines. ruff and mypy run in .ci/run, not here."""

from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
MAX_LINES = 300
SIZED = ("fmu_src", "benchmarks", "examples", "tools", "tests")
SUFFIXES = (".py", ".c", ".h")


def _oversized(root: Path, folders=SIZED) -> dict:
    """{path: line count} of the sources under `folders` longer than MAX_LINES;
    hidden folders (a venv) and caches are not sources."""
    found = {}
    for folder in folders:
        for path in sorted((root / folder).rglob("*")):
            parts = path.relative_to(root).parts
            if path.suffix not in SUFFIXES or not path.is_file():
                continue
            if any(p.startswith(".") or p == "__pycache__" for p in parts):
                continue
            count = len(path.read_text(encoding="utf-8", errors="replace").splitlines())
            if count > MAX_LINES:
                found[path.relative_to(root).as_posix()] = count
    return found


def test_no_module_is_over_300_lines():
    sources = [p for f in SIZED for p in (ROOT / f).rglob("*") if p.suffix in SUFFIXES]
    # An empty scan (folders renamed) would pass without checking anything.
    assert len(sources) > 50 and any(p.suffix == ".c" for p in sources)
    offenders = _oversized(ROOT)
    assert not offenders, f"over {MAX_LINES} lines: " + ", ".join(
        f"{path} ({count})" for path, count in offenders.items()
    )


def test_the_size_check_names_an_offender_and_its_count(tmp_path):
    (tmp_path / "examples").mkdir()
    (tmp_path / "examples" / "long.py").write_text("x = 1\n" * (MAX_LINES + 1))
    (tmp_path / "examples" / "short.c").write_text("int x;\n" * MAX_LINES)
    (tmp_path / "examples" / ".venv").mkdir()
    (tmp_path / "examples" / ".venv" / "big.py").write_text("x = 1\n" * 1000)
    assert _oversized(tmp_path, ("examples",)) == {"examples/long.py": MAX_LINES + 1}
