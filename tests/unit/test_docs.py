"""The docs say each thing once, as the code holds it: commands called one way,
the model table from the models found, figures from the benchmark results."""

import re

import doc_commands
import pytest
from test_readme import DOCS, ROOT


def test_every_command_calls_the_venvs_tools_one_way():
    """Every page calls the tools the one way the README's set-up makes them:
    `.venv/bin/...`, with no venv to activate."""
    pages = doc_commands.pages()
    assert len([c for page in pages for c in doc_commands.commands(page)]) > 20
    assert [line for page in pages for line in doc_commands.unlike_the_rest(page)] == []


def test_the_command_check_names_a_bare_tool(tmp_path):
    page = tmp_path / "page.md"
    page.write_text(
        "Run `python build_fmu.py --model Load` or\n\n    cardan-joint simulate\n"
        "    .venv/bin/python build_fmu.py\n\n    omega = 2 pi f\n"
    )
    with pytest.MonkeyPatch.context() as patch:
        patch.setattr(doc_commands, "ROOT", tmp_path)
        assert doc_commands.unlike_the_rest(page) == [
            "page.md:3: cardan-joint simulate",
            "page.md:1: python build_fmu.py --model Load",
        ]


# A measured figure: a time per step, a memory size, a rate, or a ratio (x1.29).
FIGURE = re.compile(
    r"(?<![\w.])(\d[\d,.]*(?:e[+-]?\d+)?)\s?(µs|us|ns|MiB|samples/s)\b|(?:×|\bx)(\d+(?:\.\d+)?)\b"
)


def unsourced_figures(text: str, results: str) -> list:
    """The measured figures of `text` that `results` does not hold, goals
    (after <= or >=) apart."""
    found = []
    for match in FIGURE.finditer(text):
        before = text[max(0, match.start() - 2) : match.start()]
        if "≤" in before or "≥" in before or "<=" in before or ">=" in before:
            continue
        if match.group(0).replace(" ", "") not in results.replace(" ", ""):
            found.append(match.group(0))
    return found


def test_every_figure_in_the_docs_is_in_the_benchmark_results():
    results = (ROOT / "benchmarks" / "results.md").read_text()
    pages = [ROOT / "README.md", *sorted(DOCS.glob("*.md"))]
    unsourced = {p.name: unsourced_figures(p.read_text(), results) for p in pages}
    assert {page: found for page, found in unsourced.items() if found} == {}


def test_the_figure_check_names_a_figure_not_in_the_results():
    results = "| joint 28.3 µs, floor 21.9 µs: **×1.29** |"
    text = "The joint takes 28.3 µs (×1.29, goal ≤ ×1.3); the C host 6.2 µs, ×1.06."
    assert unsourced_figures(text, results) == ["6.2 µs", "×1.06"]


# A user page states what holds; where it is tested is contributing.md's table.
# contributing.md and runtime.md are the maintainers' pages: they name tests.
MAINTAINER_PAGES = {"contributing.md", "runtime.md"}
TEST_PATH = re.compile(r"(?<![\w/.])tests/|\btest_\w+\.py\b")


def test_no_user_page_names_a_test_file():
    pages = [p for p in doc_commands.pages() if p.name not in MAINTAINER_PAGES]
    assert len(pages) > 10  # an empty scan would pass
    named = [
        f"{page.relative_to(ROOT)}:{number}: {line.strip()}"
        for page in pages
        for number, line in enumerate(page.read_text().splitlines(), 1)
        if TEST_PATH.search(line)
    ]
    assert named == [], "move these to docs/contributing.md's table:\n" + "\n".join(named)


def test_the_test_path_check_sees_a_path_and_a_bare_test_file():
    assert TEST_PATH.search("checked (`tests/fmu/test_x.py`)")
    assert TEST_PATH.search("see `test_life.py`")
    assert not TEST_PATH.search("the tests pass; contests/ latest")
