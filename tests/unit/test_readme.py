"""The README and the docs stay true: commands, size, model pages, tables, links."""

import re
import shutil
import subprocess
from pathlib import Path

import pytest

from cardan_joint.models import discover

ROOT = Path(__file__).resolve().parents[2]
README = (ROOT / "README.md").read_text()
DOCS = ROOT / "docs"
TEST_COMMAND = (
    'python3 -m venv .venv && .venv/bin/pip install -e ".[test]" && .venv/bin/python -m pytest'
)
CI = ROOT / ".ci" / "run"


def ci_block(readme: str) -> list:
    """The README's commands between its ci marks: indented code lines, in order."""
    block = readme.partition("<!-- ci:begin -->\n")[2].partition("<!-- ci:end -->")[0]
    return [line[4:] for line in block.splitlines() if line.startswith("    ")]


def ci_lists(top: Path) -> list:
    """The commands `.ci/run` in `top` would run, as it lists them."""
    run = subprocess.run(
        ["bash", str(top / ".ci" / "run"), "--list"], capture_output=True, text=True, check=True
    )
    return run.stdout.splitlines()


def beside(top: Path, readme: str) -> None:
    """A copy of `.ci/run` in `top`, with `readme` as the README it reads."""
    (top / ".ci").mkdir()
    shutil.copy(CI, top / ".ci" / "run")
    (top / "README.md").write_text(readme)


def test_the_readme_is_read_in_five_minutes():
    assert len(README.splitlines()) <= 250


def test_the_readmes_test_set_up_names_the_system_packages_and_runs_the_tests():
    commands = ci_block(README)
    assert any(TEST_COMMAND in command for command in commands)
    set_up = next(command for command in commands if TEST_COMMAND in command)
    assert set_up.startswith("apt-get update && apt-get install -y ")
    assert "debootstrap" in set_up.split(" && ")[1].split()  # the Debian 11 root's


def test_ci_runs_exactly_the_readmes_commands():
    assert ci_lists(ROOT) == ci_block(README)
    # ... and calls no program of its own: every tool is in the README's lines.
    code = [line for line in CI.read_text().splitlines() if not line.lstrip().startswith("#")]
    for tool in ("apt-get", "pip", "pytest", "python", "ruff", "mypy"):
        assert not any(re.search(rf"\b{tool}\b", line) for line in code), f".ci/run calls {tool}"


def test_a_package_added_to_the_readme_is_one_ci_installs(tmp_path):
    beside(tmp_path, README.replace("python3-venv ", "python3-venv gdb "))
    assert ci_lists(tmp_path)[0] == ci_block(README)[0].replace(
        "python3-venv ", "python3-venv gdb "
    )


def test_ci_runs_each_line_in_order_and_stops_at_the_first_failure(tmp_path):
    lines = ["printf 'one\\n' > out", "printf 'two\\n' >> out && false", "printf 'three\\n' >> out"]
    block = "".join(f"    {line}\n" for line in lines)
    beside(tmp_path, f"# R\n\n<!-- ci:begin -->\n\n{block}\n<!-- ci:end -->\n")
    run = subprocess.run(["bash", str(tmp_path / ".ci" / "run")], capture_output=True, text=True)
    assert run.returncode != 0
    assert (tmp_path / "out").read_text() == "one\ntwo\n"


def test_ci_without_the_readmes_marks_fails(tmp_path):
    beside(tmp_path, README.replace("<!-- ci:begin -->", ""))
    with pytest.raises(subprocess.CalledProcessError):
        ci_lists(tmp_path)


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
