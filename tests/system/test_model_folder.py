"""A model is one folder (issues 19, 25): copying one model's folder under a new
name and renaming the model inside that folder only gives a new model whose
FMUs (FMI 2.0 and 3.0) build, validate and simulate, whose reference run the
suite's own checks regenerate and reproduce through its FMU, and which the docs
list: `tools/model_pages.py` adds it to the generated index block of README.md,
and no other file outside the new folder changes (no hand
edit anywhere). Done in a copy of the project: the tree is left alone. A system
test (the slow layer): it copies the project, builds its FMUs there and runs part
of the suite in it.

Known, not this module's: after an FMI 2.0 FMU is simulated in-process, the
FMU's own `pythonfmu` stays in sys.modules (from its deleted resources folder),
so a later in-process build in the same session finds no binaries there
(tests/test_build.py run after this module; fmi/native's to fix)."""

import hashlib
import os
import re
import shutil
import subprocess
import sys
import zipfile
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
PACKAGE = Path("fmu_src") / "cardan_joint"
# The copy holds the whole checkout but what is built, cached or installed
# (.gitignore's entries but /build/, a name the package uses too; git, caches).
LEFT_OUT = (".git", ".venv", "dist", "out", "results", ".pytest_cache", ".hypothesis")
IGNORED = shutil.ignore_patterns(
    *LEFT_OUT, ".ruff_cache", ".mypy_cache", "*.egg-info", "__pycache__"
)
# The generated index blocks: the only text outside the new folder that changes.
INDEXES = (Path("README.md"),)
MODEL_INDEX = re.compile(r"<!-- models:begin -->\n.*?<!-- models:end -->", re.DOTALL)


def _files(tree: Path):
    """The files a copy holds (IGNORED pruned as copytree prunes it), but the new folder."""
    for folder, subfolders, files in os.walk(tree):
        here = Path(folder)
        left_out = set(IGNORED(folder, subfolders + files))
        subfolders[:] = [d for d in subfolders if d not in left_out and d != "brake"]
        yield from (here / name for name in sorted(files) if name not in left_out)


def _digests(tree: Path) -> dict:
    """Every file's digest, the generated index blocks left out of the indexes."""
    digests = {}
    for path in _files(tree):
        relative = path.relative_to(tree)
        data = path.read_bytes()
        if relative in INDEXES:
            data = MODEL_INDEX.sub("", data.decode()).encode()
        digests[relative] = hashlib.sha256(data).hexdigest()
    return digests


def _run(copy: Path, *args: str, timeout: float = 600) -> subprocess.CompletedProcess:
    """A command in the copy, importing the copy's package (not the installed one)."""
    env = {**os.environ, "PYTHONPATH": str(copy / "fmu_src")}
    env.pop("PYTEST_ADDOPTS", None)
    return subprocess.run(
        [sys.executable, *args], cwd=copy, env=env, capture_output=True, text=True, timeout=timeout
    )


def _copy_load_as_brake(copy: Path) -> None:
    """models/brake/: models/load/ with the model renamed `Load` -> `Brake` in its
    files and their names, nothing else touched."""
    models = copy / PACKAGE / "models"
    shutil.copytree(models / "load", models / "brake", ignore=IGNORED)
    for path in sorted((models / "brake").iterdir()):
        text = path.read_text()
        for old, new in (("models.load", "models.brake"), ("models/load", "models/brake")):
            text = text.replace(old, new)
        path.write_text(text.replace("Load", "Brake"))
        if "Load" in path.name:
            path.rename(path.with_name(path.name.replace("Load", "Brake")))


@pytest.fixture(scope="module")
def brake_project(tmp_path_factory):
    """A copy of the project with models/brake/, its FMUs built (FMI 2.0 and 3.0)
    and the docs' generated blocks rewritten by their generator."""
    copy = tmp_path_factory.mktemp("brake_project") / "project"
    shutil.copytree(ROOT, copy, ignore=IGNORED)
    _copy_load_as_brake(copy)
    for version in ("2", "3"):
        run = _run(copy, "build_fmu.py", "--model", "Brake", "--fmi-version", version)
        assert run.returncode == 0, run.stdout + run.stderr
    run = _run(copy, "tools/model_pages.py")
    assert run.returncode == 0, run.stdout + run.stderr
    return copy


@pytest.mark.parametrize("fmu", ["Brake.fmu", "fmi3/Brake.fmu"])
def test_the_copied_folder_builds_valid_fmus(brake_project, fmu):
    from fmpy.validation import validate_fmu

    path = brake_project / "dist" / fmu
    assert path.is_file()
    assert validate_fmu(str(path)) == []
    with zipfile.ZipFile(path) as archive:
        shipped = [n for n in archive.namelist() if n.endswith("/models/brake/model.py")]
        assert len(shipped) == 1 and "class Brake(" in archive.read(shipped[0]).decode()
        assert 'modelName="Brake"' in archive.read("modelDescription.xml").decode()


@pytest.mark.parametrize("fmu", ["Brake.fmu", "fmi3/Brake.fmu"])
def test_the_new_fmu_simulates_its_own_model(brake_project, fmu):
    from cardan_joint.simulate import simulate

    start = {"inertia": 0.3, "drag": 0.2, "constant_torque": 5.0}
    inputs = {"speed": 10.0, "acceleration": 2.0}
    result = simulate(
        brake_project / "dist" / fmu,
        stop_time=0.01,
        output_interval=1e-3,
        inputs=inputs,
        start_values=start,
    )
    expected = 0.3 * 2.0 + 0.2 * 10.0 + 5.0  # J a + c omega + T0, the Load's law
    assert result["torque"][-1] == pytest.approx(expected, rel=1e-12)
    assert result.dtype.names == ("time", "torque")


def _suite_module(copy: Path, name: str) -> str:
    (found,) = sorted(copy.glob(f"tests/**/{name}"))
    return str(found.relative_to(copy))


def test_the_suites_own_checks_take_the_new_model(brake_project):
    """The reference run regenerated byte for byte and reproduced by the Brake
    FMU, its page present, the docs' blocks current, no generic layer naming it:
    the suite's checks, run in the copy, find the new model by discovery."""
    modules = (
        "test_model_references.py",
        "test_readme.py",
        "test_model_pages.py",
        "test_generic_layers.py",
        "test_model_package_data.py",
    )
    paths = [_suite_module(brake_project, m) for m in modules]
    # The other models' reference runs are the suite's to check, not this copy's.
    only = "Brake or not test_reference_files_are_current"
    run = _run(
        brake_project, "-m", "pytest", "-p", "no:cacheprovider", "-q", "-rA", "-k", only, *paths
    )
    assert run.returncode == 0, run.stdout[-4000:] + run.stderr[-2000:]
    passed = set(re.findall(r"^PASSED (\S+)", run.stdout, re.MULTILINE))
    for test in (
        "test_reference_files_are_current_and_the_fmu_reproduces_them[Brake]",
        "test_every_model_the_build_offers_has_its_page[Brake]",
        "test_every_generated_block_is_current",
        "test_the_index_links_every_model_discovery_finds",
    ):
        assert any(node.split("::")[-1].startswith(test) for node in passed), test


def test_the_docs_index_lists_the_new_model(brake_project):
    for index in INDEXES:
        text = (brake_project / index).read_text()
        assert re.search(
            r"\| \[Brake\]\([./]*fmu_src/cardan_joint/models/brake/README\.md\) \|", text
        )
        assert (
            "# Brake:" in (brake_project / PACKAGE / "models" / "brake" / "README.md").read_text()
        )


def test_no_file_but_the_new_folder_and_the_generated_index_differs(brake_project):
    assert _digests(brake_project) == _digests(ROOT)
    assert not (ROOT / PACKAGE / "models" / "brake").exists()
    brake = brake_project / PACKAGE / "models" / "brake"
    assert {p.name for p in brake.iterdir() if p.is_file()} == {
        p.name.replace("Load", "Brake")
        for p in (ROOT / PACKAGE / "models" / "load").iterdir()
        if p.is_file()
    }
