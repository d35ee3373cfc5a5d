"""Session fixtures: the FMU is built once, by the same command a user runs."""

import os
import shutil
import subprocess
import sys
from pathlib import Path

import pytest
from hypothesis import settings

# Local runs explore new examples each time; CI replays a fixed set so that a
# landing never hinges on a lucky draw.
settings.register_profile("ci", derandomize=True, deadline=None, print_blob=True)
if os.environ.get("CI"):
    settings.load_profile("ci")

ROOT = Path(__file__).resolve().parents[1]


def build_fmu(dest: Path, *args: str) -> Path:
    """Run build_fmu.py in its own process, as a user would."""
    command = [sys.executable, str(ROOT / "build_fmu.py"), "--dest", str(dest), *args]
    result = subprocess.run(command, capture_output=True, text=True, cwd=ROOT)
    assert result.returncode == 0, result.stdout + result.stderr
    name = next((a.split("=", 1)[1] for a in args if a.startswith("--name=")), "UniversalJoint")
    return dest / ("fmi3" if "--fmi-version=3" in args else "") / f"{name}.fmu"


@pytest.fixture(scope="session")
def fmu_path(tmp_path_factory) -> Path:
    return build_fmu(tmp_path_factory.mktemp("fmu"))


@pytest.fixture(scope="session")
def unzipped_fmu(fmu_path, tmp_path_factory):
    from fmpy import extract

    directory = extract(str(fmu_path), unzipdir=str(tmp_path_factory.mktemp("unzipped")))
    yield directory
    shutil.rmtree(directory, ignore_errors=True)


@pytest.fixture(scope="session")
def model_description(fmu_path):
    from fmpy import read_model_description

    return read_model_description(str(fmu_path))


@pytest.fixture(scope="session")
def propshaft_fmu_path(tmp_path_factory) -> Path:
    """dist/Propshaft.fmu as `build_fmu.py --model Propshaft` writes it."""
    dest = tmp_path_factory.mktemp("propshaft")
    build_fmu(dest, "--model", "Propshaft")
    return dest / "Propshaft.fmu"


@pytest.fixture(scope="session")
def propshaft_unzipped(propshaft_fmu_path, tmp_path_factory):
    from fmpy import extract

    directory = extract(
        str(propshaft_fmu_path), unzipdir=str(tmp_path_factory.mktemp("propshaft_unzipped"))
    )
    yield directory
    shutil.rmtree(directory, ignore_errors=True)


@pytest.fixture(scope="session")
def fmi3_path(tmp_path_factory) -> Path:
    return build_fmu(tmp_path_factory.mktemp("fmu3"), "--fmi-version=3")


@pytest.fixture(scope="session")
def fmi3_unzipped(fmi3_path, tmp_path_factory):
    from fmpy import extract

    # pytest removes its old temporary directories itself.
    return extract(str(fmi3_path), unzipdir=str(tmp_path_factory.mktemp("unzipped3")))


@pytest.fixture(scope="session")
def fmi3_description(fmi3_unzipped):
    from fmpy import read_model_description

    return read_model_description(fmi3_unzipped)
