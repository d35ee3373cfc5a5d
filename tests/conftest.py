"""Session fixtures: the FMU is built once, by the same command a user runs."""

import importlib.util
import os
import shutil
import signal
import subprocess
import sys
from pathlib import Path
from types import ModuleType

import pytest
from c_host.compile import compile_concurrent, compile_host, compile_host3
from hypothesis import settings
from session_files import session_folder

# Local runs explore new examples each time; CI replays a fixed set so that a
# landing never hinges on a lucky draw.
settings.register_profile("ci", derandomize=True, deadline=None, print_blob=True)
if os.environ.get("CI"):
    settings.load_profile("ci")

# Under nohup or as a background job SIGINT or SIGHUP start ignored (children inherit it).
for _s in (signal.SIGINT, signal.SIGTERM, signal.SIGHUP):
    if signal.getsignal(_s) is signal.SIG_IGN:
        signal.signal(_s, signal.default_int_handler if _s == signal.SIGINT else signal.SIG_DFL)

ROOT = Path(__file__).resolve().parents[1]


def run_build(dest: Path, *args: str, timeout: float | None = None):
    """Run build_fmu.py in its own process, as a user would; the completed process."""
    command = [sys.executable, str(ROOT / "build_fmu.py"), "--dest", str(dest), *args]
    return subprocess.run(command, capture_output=True, text=True, cwd=ROOT, timeout=timeout)


def cardan_joint(*args, cwd: Path = ROOT):
    """Run the `cardan-joint` command in its own process; the completed process."""
    return subprocess.run(
        [sys.executable, "-m", "cardan_joint.cli", *map(str, args)],
        capture_output=True,
        text=True,
        cwd=cwd,
    )


def cardan_joint_here(capsys, *args) -> subprocess.CompletedProcess:
    """`cardan-joint` run by `cli.main` in this process, as a host runs it (the
    command leaves process-wide state as found): its exit status and output. For
    tests about what the command does, not about its process; tests/fmu/test_cli.py
    runs each command in its own process."""
    from cardan_joint import cli

    capsys.readouterr()  # what came before is not the command's
    try:
        status = cli.main([str(arg) for arg in args])
    except SystemExit as exit:  # argparse's usage errors
        status = exit.code
    out, err = capsys.readouterr()
    return subprocess.CompletedProcess(args, status, out, err)


def refused_keeping_state(model, change: dict, words, held_input: str) -> None:
    """`model` (stepped once) refuses a step after `change` with a message holding
    `words` that reads back exactly, and keeps its state but `held_input`."""
    from cardan_joint.framework import Refusal

    model.step(0.5)
    before = model.state()
    for name, value in change.items():
        setattr(model, name, value)
    problem = model.step(0.1)
    assert problem and all(word in problem.message for word in words), problem
    assert Refusal.from_message(problem.message) == problem
    after = model.state()
    after.pop(held_input), before.pop(held_input)
    assert after == before


def build_fmu(dest: Path, *args: str) -> Path:
    """Build as run_build does; the FMU's path, as the build reports it."""
    result = run_build(dest, *args)
    assert result.returncode == 0, result.stdout + result.stderr
    prefix = "built and validated "
    built = [line[len(prefix) :] for line in result.stdout.splitlines() if line.startswith(prefix)]
    assert len(built) == 1, result.stdout
    return ROOT / built[0]  # a relative path is relative to the build's cwd, ROOT


def load_example(name: str) -> ModuleType:
    """examples/<name>.py as a module, imported as a script would import it (its
    folder on sys.path, for examples/_support.py); sys.path is left as found, and
    sys.modules without the modules that came from examples/."""
    examples = ROOT / "examples"
    path, modules = list(sys.path), set(sys.modules)
    sys.path.insert(0, str(examples))
    try:
        spec = importlib.util.spec_from_file_location(f"{name}_example", examples / f"{name}.py")
        module = importlib.util.module_from_spec(spec)
        spec.loader.exec_module(module)
    finally:
        sys.path[:] = path
        # Only what came from examples/ goes: unloading a library (numpy) breaks it.
        for added in set(sys.modules) - modules:
            origin = getattr(sys.modules[added], "__file__", None)
            if origin and Path(origin).resolve().parent == examples:
                del sys.modules[added]
    return module


@pytest.fixture(scope="session")
def c_host(tmp_path_factory) -> Path:
    """tests/c_host compiled: a plain C FMI host (dlopen RTLD_LOCAL, no Python)."""
    return compile_host(tmp_path_factory.mktemp("c_host") / "host")


@pytest.fixture(scope="session")
def c_host3(tmp_path_factory) -> Path:
    """tests/c_host/host3.c compiled: the same plain host for FMI 3.0."""
    return compile_host3(tmp_path_factory.mktemp("c_host3") / "host3")


@pytest.fixture(scope="session")
def concurrent_host(tmp_path_factory) -> Path:
    """tests/c_host/concurrent compiled: starts FMUs from threads at once."""
    return compile_concurrent(tmp_path_factory.mktemp("concurrent") / "concurrent")


@pytest.fixture(scope="session")
def built(pytestconfig, tmp_path_factory):
    """built(model, fmi_version, arrays, settings) -> the FMU `build_fmu.py --model
    <model> [--fmi-version=3 [--fmi3-arrays]] [settings...]` writes, built at most
    once per test session, however many xdist workers run it: every FMU test
    shares it (a module's own build of a model is a defect). The first process
    to ask builds under a lock; the others wait and read the path it wrote."""
    import fcntl

    from cardan_joint import DEFAULT_MODEL

    fmus: dict = {}

    def fmu(
        model: str = DEFAULT_MODEL,
        fmi_version: int = 2,
        arrays: bool = False,
        settings: tuple[str, ...] = (),
    ) -> Path:
        key = model, fmi_version, arrays, settings
        if key not in fmus:
            name = f"{model}{fmi_version}{'a' if arrays else ''}{''.join(settings)}"
            dest = session_folder(pytestconfig, tmp_path_factory, "fmus") / name
            with open(f"{dest}.lock", "w") as lock:
                fcntl.flock(lock, fcntl.LOCK_EX)
                done = Path(f"{dest}.built")
                if not done.exists():
                    options = ["--model", model]
                    options += ["--fmi-version=3"] if fmi_version == 3 else []
                    options += ["--fmi3-arrays"] if arrays else []
                    shutil.rmtree(dest, ignore_errors=True)  # a build that failed half way
                    dest.mkdir()
                    done.write_text(str(build_fmu(dest, *options, *settings)))
                fmus[key] = Path(done.read_text())
        return fmus[key]

    return fmu


@pytest.fixture(scope="session")
def model_fmu(built):
    """`model_fmu(key)`: dist/<key>.fmu as `build_fmu.py --model <key>` writes it."""
    return built


@pytest.fixture(scope="session")
def fmu_path(built) -> Path:
    """The default model's FMU (`build_fmu.py` with no --model)."""
    return built()


@pytest.fixture(scope="session")
def unzipped_fmu(fmu_path, tmp_path_factory):
    from fmpy import extract

    directory = extract(str(fmu_path), unzipdir=str(tmp_path_factory.mktemp("unzipped")))
    yield directory
    shutil.rmtree(directory, ignore_errors=True)


@pytest.fixture(scope="session")
def fmu_without_life_path(built) -> Path:
    """The default model built `--no-life`: for long runs about the joint's motion
    (its other outputs are the life build's, bit for bit)."""
    return built(settings=("--no-life",))


@pytest.fixture(scope="session")
def unzipped_without_life(built, tmp_path_factory):
    """The default model built `--no-life`, extracted: for long runs about the
    joint's motion, which a life integral over every step would only slow."""
    from fmpy import extract

    fmu = built(settings=("--no-life",))
    directory = extract(str(fmu), unzipdir=str(tmp_path_factory.mktemp("unzipped_no_life")))
    yield directory
    shutil.rmtree(directory, ignore_errors=True)


@pytest.fixture(scope="session")
def model_description(fmu_path):
    from fmpy import read_model_description

    return read_model_description(str(fmu_path))


@pytest.fixture(scope="session")
def propshaft_fmu_path(built) -> Path:
    """dist/Propshaft.fmu as `build_fmu.py --model Propshaft` writes it."""
    return built("Propshaft")


@pytest.fixture(scope="session")
def propshaft_unzipped(propshaft_fmu_path, tmp_path_factory):
    from fmpy import extract

    directory = extract(
        str(propshaft_fmu_path), unzipdir=str(tmp_path_factory.mktemp("propshaft_unzipped"))
    )
    yield directory
    shutil.rmtree(directory, ignore_errors=True)


@pytest.fixture(scope="session")
def fmi3_path(built) -> Path:
    """The FMI 3.0 default model with its vectors as arrays (`--fmi3-arrays`)."""
    return built(fmi_version=3, arrays=True)


@pytest.fixture(scope="session")
def fmi3_scalar_path(built) -> Path:
    """The FMI 3.0 default model as built by default: its vectors as scalars."""
    return built(fmi_version=3)


@pytest.fixture(scope="session")
def fmi3_unzipped(fmi3_path, tmp_path_factory):
    from fmpy import extract

    # pytest removes its old temporary directories itself.
    return extract(str(fmi3_path), unzipdir=str(tmp_path_factory.mktemp("unzipped3")))


@pytest.fixture(scope="session")
def fmi3_description(fmi3_unzipped):
    from fmpy import read_model_description

    return read_model_description(fmi3_unzipped)


@pytest.fixture(scope="session")
def inertia_load_fmu_path(built) -> Path:
    """dist/InertiaLoad.fmu as `build_fmu.py --model InertiaLoad` writes it."""
    return built("InertiaLoad")


@pytest.fixture(scope="session")
def compliant_joint_fmu_path(built) -> Path:
    """dist/CompliantJoint.fmu as `build_fmu.py --model CompliantJoint` writes it."""
    return built("CompliantJoint")


@pytest.fixture(scope="session")
def motor_fmu_path(built) -> Path:
    """dist/Motor.fmu as `build_fmu.py --model Motor` writes it."""
    return built("Motor")


@pytest.fixture(scope="session")
def load_fmu_path(built) -> Path:
    """dist/Load.fmu as `build_fmu.py --model Load` writes it."""
    return built("Load")


LAYERS = {"unit": "unit", "fmu": "fmu", "system": "slow"}
# The fixtures that build an FMU or a C host: the unit layer uses none of them.
BUILDING = {"built", "model_fmu", "c_host", "c_host3", "concurrent_host"}


def pytest_collection_modifyitems(items):
    """Mark every test by its layer's folder, so `-m unit` and `-m "not slow"`
    select by where a test lives; a test outside the layers, or a unit test that
    builds an FMU through the session fixtures, is an error."""
    tests = Path(__file__).resolve().parent
    for item in items:
        folder = Path(item.fspath).resolve().relative_to(tests).parts[0]
        if folder not in LAYERS:
            raise pytest.UsageError(f"{item.nodeid}: a test module lives in tests/<layer>/")
        if folder == "unit" and BUILDING & set(getattr(item, "fixturenames", ())):
            raise pytest.UsageError(f"{item.nodeid} builds an FMU: it belongs in tests/fmu")
        item.add_marker(LAYERS[folder])
