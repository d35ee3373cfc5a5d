"""The README and the docs stay true: commands, size, model pages, tables, links."""

import re
from pathlib import Path

import pytest

from cardan_joint.models import discover

ROOT = Path(__file__).resolve().parents[2]
README = (ROOT / "README.md").read_text()
DOCS = ROOT / "docs"
TEST_COMMAND = (
    'python3 -m venv .venv && .venv/bin/pip install -e ".[test]" && .venv/bin/python -m pytest'
)


def test_the_readme_is_read_in_five_minutes():
    assert len(README.splitlines()) <= 250


def test_ci_runs_the_readmes_test_command():
    assert f"    {TEST_COMMAND}\n" in README
    ci = (ROOT / ".ci" / "run").read_text()
    assert f"\n{TEST_COMMAND}\n" in ci


@pytest.mark.parametrize("model", sorted(discover()))
def test_every_model_the_build_offers_has_its_page(model):
    page = discover()[model].page
    assert page.is_file(), f"write {page.relative_to(ROOT)}"


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
    models = [spec.page for spec in discover().values()]
    assert broken_links([ROOT / "README.md", *sorted(DOCS.rglob("*.md")), *sorted(models)]) == []


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
