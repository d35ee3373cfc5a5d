"""An FMU ships its own model (issue 35): the shared layers, the runtime, its
model's Python and its page under documentation/ (FMI's place), nothing of
another model (no other folder's code, page or reference run)."""

import subprocess
import sys
import zipfile

import pytest

from cardan_joint.models import discover

JOINT = "UniversalJoint"


def _other_models_files(names: list, own: str) -> list:
    """The entries of `names` that belong to a model folder other than `own`,
    or are any model's page or reference run by its file name."""
    found = []
    for key, spec in discover().items():
        if key == own:
            continue
        by_name = {p.name for p in spec.path.iterdir() if p.suffix in (".csv", ".opt")}
        found += [
            n for n in names if f"/models/{spec.folder}/" in n or n.rpartition("/")[2] in by_name
        ]
    return found


@pytest.mark.parametrize("fixture", ["fmu_path", "fmi3_scalar_path", "fmi3_path"])
def test_the_joint_fmu_holds_no_file_of_another_model(request, fixture):
    joint = discover()[JOINT]
    with zipfile.ZipFile(request.getfixturevalue(fixture)) as fmu:
        names = fmu.namelist()
        page = fmu.read("documentation/README.md")
    assert _other_models_files(names, JOINT) == []
    # Its own folder: its Python, every file of it; its page in documentation/ only.
    folder = f"/models/{joint.folder}/"
    own = sorted(n.partition(folder)[2] for n in names if folder in n)
    assert own == sorted(p.name for p in joint.path.glob("*.py"))
    assert page == joint.page.read_bytes()
    assert [n for n in names if n.endswith((".md", ".csv", ".opt"))] == ["documentation/README.md"]
    # No sources: pythonfmu3's C++ wrapper is not what the FMU's binary is built from.
    assert not [n for n in names if n.startswith("sources/")]


def test_the_check_finds_another_models_files():
    names = [
        "resources/cardan_joint_0/models/universal_joint/model.py",
        "resources/cardan_joint_0/models/load/model.py",
        "resources/cardan_joint_0/models/motor/__init__.py",
        "resources/x/CompliantJoint_in.csv",
    ]
    assert sorted(_other_models_files(names, JOINT)) == sorted(names[1:])


def _imported_model_folders(folder: str) -> list:
    """The model folders in sys.modules once every module of `folder` is imported,
    in a fresh interpreter: what the model's code needs, found by running it."""
    script = (
        "import importlib, pkgutil, sys\n"
        f"package = importlib.import_module('cardan_joint.models.{folder}')\n"
        "for module in pkgutil.iter_modules(package.__path__, package.__name__ + '.'):\n"
        "    importlib.import_module(module.name)\n"
        "names = [m.split('.') for m in sys.modules if m.startswith('cardan_joint.models.')]\n"
        "print(' '.join(sorted({parts[2] for parts in names})))\n"
    )
    run = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True, check=True)
    return run.stdout.split()


@pytest.mark.parametrize("fmi_version", [2, 3])
@pytest.mark.parametrize("key", sorted(discover()))
def test_every_fmu_ships_the_model_folders_its_code_imports_and_no_other(
    model_fmu, key, fmi_version
):
    spec = discover()[key]
    with zipfile.ZipFile(model_fmu(key, fmi_version)) as fmu:
        names = fmu.namelist()
        page = fmu.read("documentation/README.md")
    shipped = sorted({n.split("/models/")[1].split("/")[0] for n in names if "/models/" in n})
    assert shipped == sorted(["__init__.py", *_imported_model_folders(spec.folder)])
    assert page == spec.page.read_bytes()
