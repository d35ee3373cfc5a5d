"""The README and the docs stay true: commands, size, model pages, tables, links."""

import re
from pathlib import Path

import doc_commands
import pytest

from cardan_joint.models import MODELS
from cardan_joint.models.universal_joint.variables import fmi3_array_table, markdown_table

ROOT = Path(__file__).resolve().parents[2]
README = (ROOT / "README.md").read_text()
DOCS = ROOT / "docs"
TEST_COMMAND = (
    'python3 -m venv .venv && .venv/bin/pip install -e ".[test]" && .venv/bin/python -m pytest'
)


def between(text: str, key: str) -> str:
    begin, end = f"<!-- {key}:begin -->\n", f"<!-- {key}:end -->"
    assert text.count(begin) == 1 and text.count(end) == 1, key
    return text.split(begin)[1].split(end)[0]


def model_page(model: str) -> str:
    return (DOCS / model / "README.md").read_text()


def test_the_readme_is_read_in_five_minutes():
    assert len(README.splitlines()) <= 250


def test_ci_runs_the_readmes_test_command():
    assert f"    {TEST_COMMAND}\n" in README
    ci = (ROOT / ".ci" / "run").read_text()
    assert f"\n{TEST_COMMAND}\n" in ci


@pytest.mark.parametrize("model", sorted(MODELS))
def test_every_model_the_build_offers_has_its_page(model):
    assert (DOCS / model / "README.md").is_file(), f"write docs/{model}/README.md"


def _tables():
    from cardan_joint.models.load.variables import LOAD
    from cardan_joint.models.motor.variables import MOTOR
    from cardan_joint.models.propshaft.variables import propshaft_table

    return {
        "UniversalJoint": markdown_table(),
        "Propshaft": propshaft_table(2).markdown_table(),
        "Motor": MOTOR.markdown_table(),
        "Load": LOAD.markdown_table(),
    }


@pytest.mark.parametrize("model", ["UniversalJoint", "Propshaft", "Motor", "Load"])
def test_each_model_pages_variable_table_is_generated_from_its_table(model):
    assert between(model_page(model), "variables") == _tables()[model]


def test_fmi3_array_table_is_generated_from_the_metadata_table():
    assert between(model_page("UniversalJoint"), "fmi3-arrays") == fmi3_array_table()


def _anchors(page: Path) -> set:
    """GitHub's anchors of a markdown page's headings."""
    lines = page.read_text().splitlines()
    headings = (line.lstrip("#").strip() for line in lines if line.startswith("#"))
    return {re.sub(r"[^\w\- ]", "", h.lower()).replace(" ", "-") for h in headings}


def broken_links(pages) -> list:
    """ "<page>: <target>" for every relative link or image of `pages` whose file
    or heading anchor does not exist."""
    broken = []
    for page in pages:
        for target in re.findall(r"\]\(([^)\s]+)\)", page.read_text()):
            if re.match(r"[a-z]+://", target):
                continue
            name, _, anchor = target.partition("#")
            path = (page.parent / name).resolve() if name else page
            if not path.exists() or (anchor and anchor not in _anchors(path)):
                broken.append(f"{page.name}: {target}")
    return broken


def test_every_relative_link_and_image_resolves():
    assert broken_links([ROOT / "README.md", *sorted(DOCS.rglob("*.md"))]) == []


def test_the_link_check_names_a_missing_page_and_a_missing_heading(tmp_path):
    (tmp_path / "other.md").write_text("# Real heading\n")
    page = tmp_path / "page.md"
    page.write_text(
        "[ok](other.md#real-heading) [gone](missing.md) [bad](other.md#no-such)"
        " ![img](img/none.png) [web](https://example.org/x.md)\n"
    )
    assert broken_links([page]) == [
        "page.md: missing.md",
        "page.md: other.md#no-such",
        "page.md: img/none.png",
    ]


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


def model_table() -> str:
    """The README's model table, from the models discovery finds."""
    rows = [
        f"| [{key}](docs/{key}/README.md) | {MODELS[key].description} |" for key in sorted(MODELS)
    ]
    return "| model | what it is |\n|---|---|\n" + "\n".join(rows) + "\n"


def test_the_readmes_model_table_is_generated_from_the_models_found():
    assert between(README, "models") == model_table()


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
