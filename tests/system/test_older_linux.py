"""Issue 24, item 3, shown by running: the FMUs built here (glibc 2.36, GCC 12) run
where FMI tools run. In a Debian 11 root (glibc 2.31, GCC 10's C++ runtime) a plain
C host, compiled there by its gcc, runs both FMUs with a CPython 3.11 built there,
equal to FMPy's run here; with only Debian 11's own CPython 3.9 instantiate says
the FMU needs 3.10. Here, a host that puts an older libstdc++.so.6 (Debian 11's)
first on its library path, as MATLAB does, runs both FMUs.

The root is laid out once and cached (tests/system/debian_root.py)."""

import shutil
import tempfile
from pathlib import Path

import numpy as np
import pytest
from c_host.compile import compile_command, host_files
from debian_root import RootUnavailable, in_root, prepare
from test_c_host import HOST_RUN, SETTINGS, STEPS, run_host

pytestmark = pytest.mark.slow

MULTIARCH = "usr/lib/x86_64-linux-gnu"
FMUS = {2: ("unzipped_fmu", "fmu_path"), 3: ("fmi3_unzipped", "fmi3_path")}


@pytest.fixture(scope="session")
def bullseye():
    try:
        return prepare()
    except RootUnavailable as reason:
        pytest.skip(str(reason))


@pytest.fixture(scope="session")
def scratch(bullseye):
    """A folder inside the root, removed after the session; (path here, path there)."""
    here = Path(tempfile.mkdtemp(prefix="cardan-joint-", dir=bullseye / "tmp"))
    yield here, Path("/tmp") / here.name
    shutil.rmtree(here, ignore_errors=True)


def host_in_root(root: Path, here: Path, there: Path, fmi: int) -> Path:
    """tests/c_host's FMI 2.0 or 3.0 host, compiled inside `root` by its gcc in the
    scratch folder (`here` outside, `there` inside); its path in the root."""
    include, sources = host_files(fmi3=fmi == 3)
    folder = here / f"host{fmi}"
    shutil.copytree(include, folder / "include")
    for source in [*sources, *Path(sources[0]).parent.glob("*.h")]:
        shutil.copy(source, folder)
    inside = there / f"host{fmi}"
    command = compile_command(
        inside / "host",
        inside / "include",
        [inside / Path(source).name for source in sources],
        cc=["gcc"],
    )
    run = in_root(root, " ".join(map(str, command)), timeout=300)
    assert run.returncode == 0, run.stderr
    return inside / "host"


@pytest.fixture(scope="session")
def hosts_there(bullseye, scratch):
    """tests/c_host's FMI 2.0 and 3.0 hosts, compiled inside the root by its gcc:
    {fmi version: the host's path in the root}."""
    return {fmi: host_in_root(bullseye, *scratch, fmi) for fmi in (2, 3)}


def fmu_there(request, scratch, fmi: int) -> Path:
    here, there = scratch
    if not (here / f"fmu{fmi}").exists():
        shutil.copytree(request.getfixturevalue(FMUS[fmi][0]), here / f"fmu{fmi}")
    return there / f"fmu{fmi}"


def fmpy_columns(fmu_path, names: list) -> np.ndarray:
    """FMPy's run of HOST_RUN here, in the host's column order (arrays element-wise)."""
    from fmpy import simulate_fmu

    result = simulate_fmu(
        str(fmu_path), stop_time=STEPS * HOST_RUN[2], output_interval=HOST_RUN[2],
        start_values=SETTINGS,
    )  # fmt: skip
    columns = []
    for name in names:
        base, _, index = name.rstrip("]").partition("[")
        columns.append(result[base][:, int(index) - 1] if index else result[base])
    return np.column_stack(columns)


def assert_equals_fmpy(stdout: str, fmu_path) -> None:
    lines = stdout.splitlines()
    names = lines[0].replace('"', "").split(",")
    ours, theirs = np.loadtxt(lines[1:], delimiter=","), fmpy_columns(fmu_path, names)
    assert ours.shape == theirs.shape and len(ours) == STEPS + 1
    np.testing.assert_allclose(ours, theirs, rtol=1e-12, atol=0)


@pytest.mark.parametrize("fmi", [2, 3])
def test_a_c_host_in_debian_11_runs_the_fmu_with_a_cpython_3_11_there(
    request, bullseye, hosts_there, scratch, fmi
):
    fmu = fmu_there(request, scratch, fmi)
    command = [hosts_there[fmi], HOST_RUN[0], fmu, *HOST_RUN[1:]]
    run = in_root(bullseye, " ".join(map(str, command)), timeout=600)
    assert run.returncode == 0 and "Fatal" not in run.stderr, run.stderr[-2000:]
    assert_equals_fmpy(run.stdout, request.getfixturevalue(FMUS[fmi][1]))


PYTHON_3_9 = {
    # how the FMU meets bullseye's CPython 3.9: (environment, what the message says)
    "found on the machine": ({}, "3.10"),
    "named by the user": (
        {"CARDAN_JOINT_FMU_PYTHON_LIBRARY": f"/{MULTIARCH}/libpython3.9.so.1.0"},
        "needs CPython 3.10 or newer",
    ),
}


@pytest.mark.parametrize("fmi", [2, 3])
@pytest.mark.parametrize("case", PYTHON_3_9)
def test_with_only_debian_11s_python_3_9_instantiate_says_it_needs_3_10(
    request, bullseye, hosts_there, scratch, fmi, case
):
    environment, words = PYTHON_3_9[case]
    assert (bullseye / MULTIARCH / "libpython3.9.so.1.0").exists()
    fmu = fmu_there(request, scratch, fmi)
    variables = " ".join(f"{name}={value}" for name, value in environment.items())
    script = f"env -i PATH=/usr/bin:/bin {variables} {hosts_there[fmi]} instantiate {fmu}"
    run = in_root(bullseye, script, hide=["/usr/local"], timeout=300)
    assert run.returncode == 0 and "instance NULL" in run.stdout, run.stdout + run.stderr
    logged = [line for line in run.stderr.splitlines() if line.startswith("LOG ")]
    assert logged and any(words in line for line in logged), run.stderr


@pytest.mark.parametrize("fmi", [2, 3])
def test_a_host_with_an_older_libstdcxx_first_runs_the_fmu(
    request, bullseye, c_host, c_host3, tmp_path, fmi
):
    """Debian 11's libstdc++.so.6 (GCC 10, GLIBCXX_3.4.28) before this machine's."""
    older = bullseye / MULTIARCH / "libstdc++.so.6"
    shutil.copy(older.resolve(), tmp_path / "libstdc++.so.6")
    host = c_host if fmi == 2 else c_host3
    unzipped = request.getfixturevalue(FMUS[fmi][0])
    run = run_host(
        host, HOST_RUN[0], unzipped, *HOST_RUN[1:],
        environment={"LD_LIBRARY_PATH": str(tmp_path)}, timeout=600,
    )  # fmt: skip
    assert "instance NULL" not in run.stdout, run.stderr
    assert_equals_fmpy(run.stdout, request.getfixturevalue(FMUS[fmi][1]))
