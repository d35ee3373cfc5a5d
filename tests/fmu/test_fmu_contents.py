"""An FMU ships its own model (issue 35): the shared layers, the runtime, its
model's Python and its page under documentation/ (FMI's place), nothing of
another model (no other folder's code, page or reference run)."""

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
