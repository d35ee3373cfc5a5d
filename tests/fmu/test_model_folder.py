"""A model is a folder (issue 19): copying one model's folder under a new name,
renaming the model inside that folder only, gives a new FMU that builds,
validates and simulates. Done in a copy of the project: the tree is left alone."""

import hashlib
import shutil
import subprocess
import sys
import zipfile
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
PACKAGE = Path("fmu_src") / "cardan_joint"


def _digests(tree: Path, skip: str) -> dict:
    return {
        path.relative_to(tree): hashlib.sha256(path.read_bytes()).hexdigest()
        for path in sorted(tree.rglob("*"))
        if path.is_file() and "__pycache__" not in path.parts and skip not in path.parts
    }


@pytest.fixture(scope="module")
def brake_project(tmp_path_factory):
    """A copy of the project with models/brake/: models/load/ with `Load` -> `Brake`."""
    copy = tmp_path_factory.mktemp("brake_project")
    shutil.copytree(ROOT / PACKAGE, copy / PACKAGE, ignore=shutil.ignore_patterns("__pycache__"))
    shutil.copy2(ROOT / "build_fmu.py", copy / "build_fmu.py")
    models = copy / PACKAGE / "models"
    shutil.copytree(models / "load", models / "brake", ignore=shutil.ignore_patterns("__pycache__"))
    for path in (models / "brake").rglob("*.py"):
        text = path.read_text().replace("models.load", "models.brake").replace("Load", "Brake")
        path.write_text(text)
    run = subprocess.run(
        [sys.executable, "build_fmu.py", "--model", "Brake"],
        cwd=copy,
        capture_output=True,
        text=True,
        timeout=600,
    )
    assert run.returncode == 0, run.stdout + run.stderr
    return copy


def test_the_copied_folder_builds_a_valid_fmu(brake_project):
    from fmpy.validation import validate_fmu

    fmu = brake_project / "dist" / "Brake.fmu"
    assert fmu.is_file()
    assert validate_fmu(str(fmu)) == []
    with zipfile.ZipFile(fmu) as archive:
        shipped = [n for n in archive.namelist() if n.endswith("/models/brake/model.py")]
        assert len(shipped) == 1 and "class Brake(" in archive.read(shipped[0]).decode()
        assert 'modelName="Brake"' in archive.read("modelDescription.xml").decode()


def test_the_new_fmu_simulates_its_own_model(brake_project):
    from cardan_joint.simulate import simulate

    start = {"inertia": 0.3, "drag": 0.2, "constant_torque": 5.0}
    inputs = {"speed": 10.0, "acceleration": 2.0}
    result = simulate(
        brake_project / "dist" / "Brake.fmu",
        stop_time=0.01,
        output_interval=1e-3,
        inputs=inputs,
        start_values=start,
    )
    expected = 0.3 * 2.0 + 0.2 * 10.0 + 5.0  # J a + c omega + T0, the Load's law
    assert result["torque"][-1] == pytest.approx(expected, rel=1e-12)
    assert result.dtype.names == ("time", "torque")


def test_no_file_but_the_new_folder_differs(brake_project):
    original = _digests(ROOT / PACKAGE, "brake")
    copied = _digests(brake_project / PACKAGE, "brake")
    assert copied == original
    assert not (ROOT / PACKAGE / "models" / "brake").exists()
