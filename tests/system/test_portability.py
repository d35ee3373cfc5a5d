"""Issue 18: the FMU built here runs on machines that have none of the build's
Python, with whatever CPython 3.10-3.13 they have, in C and Python hosts.

Other machines are simulated with a private mount namespace (`unshare -m`, as
root): tmpfs hides pyenv and the build's venv; an overlay over /usr/lib lays a
pyenv CPython out as a distribution does (libpython3.X.so.1.0 in the multiarch
directory, its standard library in /usr/lib/python3.X) or removes Debian's
Python, without touching the real /usr/lib."""

import os
import shutil
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest
from test_c_host import (
    DT,
    EMPTY_ENVIRONMENT,
    HOST_RUN,
    SETTINGS,
    STEPS,
    assert_csv_equals,
    fmpy_reference,
    run_host,
)

PYENV = Path("/root/.pyenv")
MULTIARCH = Path("/usr/lib/x86_64-linux-gnu")
STDLIB_HOST = Path(__file__).resolve().parents[1] / "c_host" / "stdlib_host.py"


def pyenv_cpython(minor: int) -> Path:
    found = sorted((PYENV / "versions").glob(f"3.{minor}.*"))
    if not found or not (found[-1] / "lib" / f"libpython3.{minor}.so.1.0").exists():
        pytest.skip(f"needs pyenv's shared CPython 3.{minor} in {PYENV}/versions")
    return found[-1]


@pytest.fixture(scope="session")
def reference(fmu_path):
    return fmpy_reference(fmu_path)


@pytest.fixture(scope="session")
def namespaces(tmp_path_factory):
    """Whether this machine can simulate others: root, unshare, overlayfs."""
    scratch = tmp_path_factory.mktemp("probe")
    (scratch / "upper").mkdir(), (scratch / "work").mkdir()
    probe = (
        f"mount --make-rprivate / && mount -t overlay overlay -o lowerdir=/usr/lib,"
        f"upperdir={scratch}/upper,workdir={scratch}/work /usr/lib"
    )
    if os.geteuid() != 0 or not shutil.which("unshare"):
        pytest.skip("simulating other machines needs root and unshare (mount namespaces)")
    run = subprocess.run(["unshare", "-m", "sh", "-c", probe], capture_output=True, text=True)
    if run.returncode != 0:
        pytest.skip(f"this machine cannot make mount namespaces with overlays: {run.stderr}")


def lay_out(minor: int, library_directory: Path, stdlib_directory: Path) -> list:
    """Shell lines putting pyenv's CPython 3.<minor> library and standard library
    there, as a distribution would (bind mounts onto empty mount points)."""
    name, stdlib = f"libpython3.{minor}.so.1.0", f"python3.{minor}"
    source = pyenv_cpython(minor) / "lib"
    return [
        f"mkdir -p {library_directory} {stdlib_directory / stdlib}",
        f"touch {library_directory / name}",
        f"mount --bind {source / name} {library_directory / name}",
        f"mount --bind {source / stdlib} {stdlib_directory / stdlib}",
    ]


def machine(
    tmp_path: Path,
    *,
    debian_python: bool,
    distribution: tuple = (),
    cached: int | None = None,
    empty: int | None = None,
) -> Path:
    """A script that runs its arguments, with an empty environment, on a machine
    without the build's Python: Debian's own Python kept or removed, pyenv's
    CPythons 3.<distribution> laid out as a distribution's, and 3.<cached> in a
    folder that only the linker's cache (/etc/ld.so.cache, remade) knows."""
    upper, work = tmp_path / "upper", tmp_path / "work"
    upper.mkdir(), work.mkdir()
    lines = [
        "set -e",
        "mount --make-rprivate /",
        f"mount -t overlay overlay -o lowerdir=/usr/lib,upperdir={upper},workdir={work} /usr/lib",
    ]
    if not debian_python:
        lines += [
            f"rm -f {MULTIARCH}/libpython3*",
            "for d in /usr/lib/python3*; do mount -t tmpfs tmpfs $d; done",
        ]
    for minor in distribution:
        lines += lay_out(minor, MULTIARCH, Path("/usr/lib"))
    if empty is not None:  # 3.<empty>'s library a 0-byte file, its standard library kept
        lines.append(f"truncate -s 0 {MULTIARCH}/libpython3.{empty}.so.1.0")
    if cached is not None:
        prefix = tmp_path / "opt" / "lib"
        (tmp_path / "ld.so.conf").write_text(f"{prefix}\n")
        lines += lay_out(cached, prefix, prefix)
        lines += [
            f"ldconfig -X -C {tmp_path}/ld.so.cache -f {tmp_path}/ld.so.conf",
            f"mount --bind {tmp_path}/ld.so.cache /etc/ld.so.cache",
        ]
    hidden = {PYENV, Path(sys.prefix), Path(sys.base_prefix), Path(__file__).parents[2] / ".venv"}
    outermost = [p for p in hidden if p.is_dir() and not any(o in p.parents for o in hidden)]
    lines += [f"mount -t tmpfs tmpfs {path}" for path in sorted(outermost)]
    lines.append('exec env -i PATH=/usr/bin:/bin "$@"')
    script = tmp_path / "machine.sh"
    script.write_text("\n".join(lines) + "\n")
    return script


def run_on(script: Path, *command) -> subprocess.CompletedProcess:
    run = subprocess.run(
        ["unshare", "-m", "sh", str(script), *map(str, command)],
        capture_output=True,
        text=True,
        timeout=300,
    )
    assert "Fatal Python error" not in run.stderr and "free()" not in run.stderr, run.stderr
    return run


MACHINES = {
    "Debian 12 with only its own Python 3.11": dict(debian_python=True),
    "only a distribution's CPython 3.10": dict(debian_python=False, distribution=(10,)),
    "only a distribution's CPython 3.12": dict(debian_python=False, distribution=(12,)),
    "only a distribution's CPython 3.13": dict(debian_python=False, distribution=(13,)),
}
STARTED = {  # what the loader must have started on each machine
    "Debian 12 with only its own Python 3.11": "Python 3.11.2 from ",
    "only a distribution's CPython 3.10": f"Python 3.10.13 from {MULTIARCH}/libpython3.10.so.1.0",
    "only a distribution's CPython 3.12": f"Python 3.12.1 from {MULTIARCH}/libpython3.12.so.1.0",
    "only a distribution's CPython 3.13": f"Python 3.13.0 from {MULTIARCH}/libpython3.13.so.1.0",
}


@pytest.mark.parametrize("case", MACHINES)
def test_a_c_host_on_another_machine_equals_fmpy(
    namespaces, c_host, unzipped_fmu, reference, tmp_path, case
):
    script = machine(tmp_path, **MACHINES[case])
    run = run_on(script, c_host, HOST_RUN[0], unzipped_fmu, *HOST_RUN[1:])
    if "instance NULL" in run.stdout or run.returncode:
        assert STARTED[case] in run.stderr, run.stderr[-2000:]  # the machine's Python ran
    assert run.returncode == 0, run.stderr[-2000:]
    assert_csv_equals(run.stdout, reference)


def test_the_fmi3_fmu_on_the_3_12_machine_equals_its_run_here(
    namespaces, c_host3, fmi3_unzipped, tmp_path
):
    """The FMI 3.0 loader finds the machine's Python as the FMI 2.0 one does; its run
    here equals FMPy's to 1e-12 (tests/fmu/test_fmi3_c_host.py)."""
    script = machine(tmp_path, **MACHINES["only a distribution's CPython 3.12"])
    there = run_on(script, c_host3, HOST_RUN[0], fmi3_unzipped, *HOST_RUN[1:])
    assert there.returncode == 0 and "instance NULL" not in there.stdout, there.stderr[-2000:]
    here = run_host(c_host3, HOST_RUN[0], fmi3_unzipped, *HOST_RUN[1:])
    assert there.stdout.splitlines()[0] == here.stdout.splitlines()[0]
    ours, theirs = (np.loadtxt(r.stdout.splitlines()[1:], delimiter=",") for r in (there, here))
    assert ours.shape == theirs.shape and len(ours) == STEPS + 1
    np.testing.assert_allclose(ours, theirs, rtol=1e-12, atol=0)


CHOICES = {
    # machine: the library the loader must choose
    "Debian's 3.11 (the build's minor) before 3.12 and 3.13": (
        dict(debian_python=True, distribution=(12, 13)),
        "/x86_64-linux-gnu/libpython3.11.so.1.0",
    ),
    "the newest, 3.13 before 3.12": (
        dict(debian_python=False, distribution=(12, 13)),
        f"{MULTIARCH}/libpython3.13.so.1.0",
    ),
    "3.12 before 3.10": (
        dict(debian_python=False, distribution=(10, 12)),
        f"{MULTIARCH}/libpython3.12.so.1.0",
    ),
    "3.12 where Debian's 3.11 is a 0-byte file": (
        dict(debian_python=True, distribution=(12,), empty=11),
        f"{MULTIARCH}/libpython3.12.so.1.0",
    ),
    "3.12 known only to the linker's cache": (
        dict(debian_python=False, cached=12),
        "/opt/lib/libpython3.12.so.1.0",
    ),
}


@pytest.mark.parametrize("case", CHOICES)
def test_the_machines_python_is_chosen_in_order(namespaces, c_host, unzipped_fmu, tmp_path, case):
    """Which library was chosen shows in the message of a search path without the
    standard library (the loader refuses it before starting that Python)."""
    layout, library = CHOICES[case]
    script = machine(tmp_path, **layout)
    run = run_on(
        script, "env", "CARDAN_JOINT_FMU_PYTHON_PATH=/nowhere", c_host, "instantiate", unzipped_fmu
    )
    assert run.returncode == 0 and "instance NULL" in run.stdout, run.stderr
    assert "the search path '/nowhere' for Python " in run.stderr, run.stderr
    chosen = run.stderr.split("for Python ", 1)[1].split(" has no standard library")[0]
    assert chosen.endswith(library), (chosen, library)


@pytest.mark.parametrize("fmi", [2, 3])
def test_with_no_python_on_the_machine_instantiate_says_so(namespaces, request, tmp_path, fmi):
    host, fmu = (
        (request.getfixturevalue("c_host"), request.getfixturevalue("unzipped_fmu"))
        if fmi == 2
        else (request.getfixturevalue("c_host3"), request.getfixturevalue("fmi3_unzipped"))
    )
    script = machine(tmp_path, debian_python=False)
    run = run_on(script, host, "instantiate", fmu)
    assert run.returncode == 0 and "instance NULL logger_calls 1" in run.stdout, run.stderr
    for words in ("no Python for this FMU", "/etc/ld.so.cache", "CARDAN_JOINT_FMU_PYTHON_LIBRARY"):
        assert words in run.stderr, (words, run.stderr)


def test_a_python_without_numpy_hosts_it(unzipped_fmu, reference):
    """Debian's /usr/bin/python3.11 has no numpy (and links libpython statically)."""
    python = Path("/usr/bin/python3.11")
    if not python.exists():
        pytest.skip("needs Debian's /usr/bin/python3.11")
    if subprocess.run([python, "-c", "import numpy"], capture_output=True).returncode == 0:
        pytest.skip(f"{python} has numpy: not a Python without numpy")
    host = [python, "-I", STDLIB_HOST, unzipped_fmu, STEPS, DT]
    run = subprocess.run(
        [*map(str, host), *(f"{name}={value!r}" for name, value in SETTINGS.items())],
        capture_output=True,
        text=True,
        env=EMPTY_ENVIRONMENT,
        timeout=300,
    )
    assert run.returncode == 0 and "instance NULL" not in run.stdout, run.stderr[-2000:]
    values = dict(line.split("=") for line in run.stdout.splitlines())
    for name in ("output_angle", "output_speed", "input_torque"):
        assert float(values[name]) == pytest.approx(reference[name][-1], rel=1e-12, abs=0)


def test_a_python_older_than_3_10_is_told_so(unzipped_fmu):
    python = pyenv_cpython(9) / "bin" / "python3"
    run = subprocess.run(
        [str(python), "-I", str(STDLIB_HOST), str(unzipped_fmu), "1", "0.001"],
        capture_output=True,
        text=True,
        env=EMPTY_ENVIRONMENT,
        timeout=120,
    )
    assert run.returncode == 0 and "instance NULL" in run.stdout, run.stderr
    assert "needs CPython 3.10 or newer, but the Python of this process is 3.9" in run.stderr


@pytest.fixture(scope="session")
def fmpy_in(tmp_path_factory):
    """fmpy_in(minor): the python of a throwaway venv of pyenv's 3.<minor> with FMPy."""
    made = {}

    def make(minor: int) -> Path:
        if minor not in made:
            venv = tmp_path_factory.mktemp(f"fmpy3{minor}")
            python = pyenv_cpython(minor) / "bin" / "python3"
            for command in (
                [python, "-m", "venv", venv],
                [venv / "bin" / "python", "-m", "pip", "install", "-q", "fmpy"],
            ):
                run = subprocess.run(command, capture_output=True, text=True, timeout=600)
                if run.returncode != 0:
                    pytest.skip(f"cannot install FMPy for Python 3.{minor}: {run.stderr[-500:]}")
            made[minor] = venv / "bin" / "python"
        return made[minor]

    return make


@pytest.mark.parametrize("minor", [10, 12, 13])
def test_fmpy_on_another_python_equals_the_builds(fmpy_in, fmu_path, reference, tmp_path, minor):
    python, saved = fmpy_in(minor), tmp_path / "result.npy"
    script = (
        "import sys, numpy\n"
        "from fmpy import simulate_fmu\n"
        f"r = simulate_fmu({str(fmu_path)!r}, stop_time={STEPS * DT!r}, output_interval={DT!r},"
        f" start_values={SETTINGS!r})\n"
        f"numpy.save({str(saved)!r}, r)\n"
        "print(sys.version_info[:2])\n"
    )
    run = subprocess.run(
        [str(python), "-c", script], capture_output=True, text=True, env=EMPTY_ENVIRONMENT
    )
    assert run.returncode == 0 and f"(3, {minor})" in run.stdout, run.stderr[-2000:]
    ours = np.load(saved)
    assert ours.dtype.names == reference.dtype.names and len(ours) == STEPS + 1
    for name in reference.dtype.names:
        np.testing.assert_allclose(ours[name], reference[name], rtol=1e-12, atol=0, err_msg=name)
