"""No generic layer names a model: fmi/, host/, build/, the stepped-model
framework (framework/) and the C generator (codegen/) work from what discovery
finds, so a model added as a folder needs nothing there. The names are
discovery's own (each model's key, folder and physics class), so a new model is
checked as soon as its folder exists."""

import re

import pytest
from conftest import ROOT

from cardan_joint.models import discover

PACKAGE = ROOT / "fmu_src" / "cardan_joint"
LAYERS = ("fmi", "host", "build", "framework", "codegen")
FRAMEWORK = (
    "__init__.py",
    "models/__init__.py",
    "variable_schema.py",
    "names.py",
    "units.py",
    "results.py",
)
# A driveline of named models (Motor -> drive -> Load) is an application of the
# models, not a layer under them: it names the models it couples.
APPLICATIONS = ("host/driveline_system.py",)
SOURCES = (".py", ".c", ".h")
# The project's default model (what a command builds when none is named) is
# declared once, at the package's top: the layers read it from there.
DEFAULT_DECLARATION = re.compile(r'^DEFAULT_MODEL = "\w+"$', re.MULTILINE)


def model_names() -> set[str]:
    names = set()
    for key, spec in discover().items():
        names |= {key, f"models.{spec.folder}", f"models/{spec.folder}"}
        names.add(type(spec.make(spec.default_settings)).__name__)
    return names


def generic_files():
    for layer in LAYERS:
        for path in sorted((PACKAGE / layer).rglob("*")):
            relative = path.relative_to(PACKAGE).as_posix()
            if path.suffix in SOURCES and relative not in APPLICATIONS:
                yield path
    for relative in FRAMEWORK:
        yield PACKAGE / relative


def named_models(text: str, names) -> list[str]:
    pattern = re.compile(r"(?<!\w)(" + "|".join(map(re.escape, sorted(names))) + r")\b")
    return sorted({match.group(1) for match in pattern.finditer(text)})


def test_every_framework_module_listed_exists():
    # A moved framework module must be listed again, not silently dropped.
    assert [p for p in (PACKAGE / f for f in FRAMEWORK + APPLICATIONS) if not p.is_file()] == []


@pytest.mark.parametrize(
    "path", list(generic_files()), ids=lambda p: p.relative_to(PACKAGE).as_posix()
)
def test_no_generic_module_names_a_model(path):
    text = DEFAULT_DECLARATION.sub("", path.read_text())
    assert named_models(text, model_names()) == [], path


def test_the_check_finds_a_model_named_in_code_or_in_a_comment():
    names = model_names()
    assert named_models('DEFAULT = "UniversalJoint"', names) == ["UniversalJoint"]
    assert named_models("from ..models.load.variables import LOAD", names) == ["models.load"]
    assert named_models("# the Propshaft has no bend angle", names) == ["Propshaft"]
    assert named_models("load_torque, self.load, InertiaLoads", names) == []
