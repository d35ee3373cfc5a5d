"""What the docs say about the models is generated from the models: the index in
README.md lists every model discovery finds, and each model's page lists its
table's variables (indexed rows as `joint_<k>_...`, rows shared with a base
model's page by a link) and FMI 3 arrays as the code has them. One check over
discovery for every model, instead of a hand-kept list per test."""

import importlib.util
import re

import pytest
from conftest import ROOT

from cardan_joint.models import discover

spec = importlib.util.spec_from_file_location("model_pages", ROOT / "tools" / "model_pages.py")
model_pages = importlib.util.module_from_spec(spec)
spec.loader.exec_module(model_pages)


def test_every_generated_block_is_current():
    assert model_pages.stale() == [], "run python tools/model_pages.py"


@pytest.mark.parametrize("page", model_pages.INDEXES, ids=lambda p: p.parent.name)
def test_the_index_links_every_model_discovery_finds(page):
    index = model_pages.model_index(page)
    for key, model in discover().items():
        assert f"[{key}](" in index and model.description in index
        assert (page.parent / index.split(f"[{key}](")[1].split(")")[0]).resolve() == model.page


def _patterns(text: str) -> list:
    """The `names` of `text`, as patterns (`joint_<k>_x`: any k)."""
    return [re.compile(re.escape(n).replace("<k>", r"\d+")) for n in re.findall(r"`([^`]+)`", text)]


def _model_at(page, link: str):
    return next(m for m in discover().values() if m.page == (page.page.parent / link).resolve())


def _listed(page) -> list:
    """The names a page's variable block lists, as patterns, with those of the
    page it takes rows from, but the ones it leaves out, and those of the page
    whose added rows it names ("and those [Model](page) adds to its own base")."""
    block = model_pages.page_blocks(page)["variables"]
    head, _, rest = block.partition("\n\n") if block.startswith("Every") else ("", "", block)
    names = _patterns(rest)
    if head:
        link, *donor = [part.split(")")[0] for part in head.split("](")[1:]]
        left = re.findall(r"`([^`]+)`", head.partition(" but ")[2])
        names += [
            p for p in _listed(_model_at(page, link)) if not any(p.fullmatch(n) for n in left)
        ]
        for other in donor:
            added = model_pages.page_blocks(_model_at(page, other))["variables"]
            names += _patterns(added.partition("\n\n")[2])
    return names


def test_every_models_page_has_its_variable_table():
    for model in discover().values():
        listed = _listed(model)
        assert [o for o in model.table().OUTPUTS if not any(p.fullmatch(o) for p in listed)] == []


def test_a_stale_block_is_found_and_rewritten(tmp_path, monkeypatch):
    page = tmp_path / "README.md"
    page.write_text("# Index\n\n<!-- models:begin -->\nold\n<!-- models:end -->\n")
    monkeypatch.setattr(model_pages, "expected", lambda: {page: {"models": "new\n"}})
    monkeypatch.setattr(model_pages, "ROOT", tmp_path)
    assert model_pages.stale() == ["README.md: models"]
    assert model_pages.rewrite() == [page]
    assert page.read_text() == "# Index\n\n<!-- models:begin -->\nnew\n<!-- models:end -->\n"
    assert model_pages.stale() == []


def test_a_page_without_its_markers_is_named(tmp_path, monkeypatch):
    page = tmp_path / "README.md"
    page.write_text("# A model\n")
    monkeypatch.setattr(model_pages, "expected", lambda: {page: {"variables": "table\n"}})
    assert any("<!-- variables:begin -->" in problem for problem in model_pages.stale())
