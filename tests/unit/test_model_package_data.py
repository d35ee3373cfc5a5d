"""Every file of a model's folder is installed with the package: `build
--cross-check` copies the page and the reference run beside the FMU, so an
installed (non-editable) package must carry them, not only a checkout."""

import fnmatch
import functools

import pytest
from conftest import ROOT

from cardan_joint.models import MODELS_DIR, discover

PACKAGE = MODELS_DIR.parent
# setuptools calls its pyproject [tool.setuptools] support beta; the read is right.
pytestmark = pytest.mark.filterwarnings("ignore:Support for `\\[tool.setuptools\\]`")


@functools.cache
def _patterns() -> tuple:
    """pyproject's package-data patterns, read once (setuptools validates the
    whole file at each read)."""
    from setuptools.config.pyprojecttoml import read_configuration  # tomllib: 3.11+

    config = read_configuration(ROOT / "pyproject.toml")
    return tuple(config["tool"]["setuptools"]["package-data"]["cardan_joint"])


def _installed(path) -> bool:
    patterns = _patterns()
    relative = path.relative_to(PACKAGE).as_posix()
    return path.suffix == ".py" or any(fnmatch.fnmatch(relative, p) for p in patterns)


def test_every_file_of_every_model_folder_is_package_data():
    missing = [
        path.relative_to(PACKAGE).as_posix()
        for spec in discover().values()
        for path in sorted(spec.path.rglob("*"))
        if path.is_file() and "__pycache__" not in path.parts and not _installed(path)
    ]
    assert missing == []


def test_a_file_the_patterns_miss_is_found():
    assert not _installed(MODELS_DIR / "some_model" / "notes.txt")
    assert _installed(MODELS_DIR / "some_model" / "README.md")
