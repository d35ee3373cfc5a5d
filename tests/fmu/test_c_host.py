"""The FMU in a C host, loaded as an FMI tool loads it: dlopen RTLD_LOCAL, empty
environment, no Python of its own (tests/c_host/host.c, compiled here with cc)."""

import shutil
import subprocess
import sys
import zipfile
from pathlib import Path

import numpy as np
import pytest

from cardan_joint.fmi.native import search_path, shared_libpython

EMPTY_ENVIRONMENT = {"PATH": "/usr/bin:/bin"}
STEPS, DT = 10_000, 1e-3
SETTINGS = {
    "input_speed": 40.0,
    "input_acceleration": 3.0,
    "bend_angle": 0.4,
    "bend_angle_rate": 0.01,
    "load_torque": 50.0,
    "yoke_phase": 0.3,
}
HOST_RUN = ("run", STEPS, DT, *(f"{name}={value!r}" for name, value in SETTINGS.items()))


def fmpy_reference(fmu_path):
    """FMPy's run of HOST_RUN in this process (the build's Python)."""
    from fmpy import simulate_fmu

    return simulate_fmu(
        str(fmu_path), stop_time=STEPS * DT, output_interval=DT, start_values=SETTINGS
    )


def assert_csv_equals(stdout: str, reference) -> None:
    """The host's CSV of a HOST_RUN equals FMPy's to 1e-12 relative, every column."""
    names = stdout.splitlines()[0].replace('"', "").split(",")
    ours = np.loadtxt(stdout.splitlines()[1:], delimiter=",")
    assert ours.shape == (len(reference), len(names)) and len(reference) == STEPS + 1
    for column, name in enumerate(names):
        np.testing.assert_allclose(
            ours[:, column], reference[name], rtol=1e-12, atol=0, err_msg=name
        )


def run_host(c_host, *args, timeout=120, environment=None, fatal_logged=False):
    """The host's run, which must end cleanly (no crash, no abort at exit); a fatal
    status in the logger only where the case expects the slave to report one."""
    run = subprocess.run(
        [str(c_host), *map(str, args)],
        env={**EMPTY_ENVIRONMENT, **(environment or {})},
        capture_output=True,
        text=True,
        timeout=timeout,
    )
    assert run.returncode == 0, run.stdout[-2000:] + run.stderr[-2000:]
    crashed = "Fatal Python error" in run.stderr or "free()" in run.stderr
    assert not crashed and (fatal_logged or "Fatal" not in run.stderr), run.stderr[-2000:]
    return run


def fmu_copy_with_record(unzipped_fmu, tmp_path, edit):
    """An extracted copy of the FMU whose resources/python_runtime.txt `edit` rewrites."""
    copy = tmp_path / "fmu"
    shutil.copytree(unzipped_fmu, copy)
    record = copy / "resources" / "python_runtime.txt"
    record.write_text(edit(record.read_text()))
    return copy


def test_c_host_equals_fmpy_over_ten_thousand_steps(c_host, fmu_path, unzipped_fmu):
    run = run_host(c_host, HOST_RUN[0], unzipped_fmu, *HOST_RUN[1:])
    assert_csv_equals(run.stdout, fmpy_reference(fmu_path))


def test_a_bad_input_with_logging_off_reaches_the_logger_once(c_host, unzipped_fmu):
    run = run_host(c_host, "bad", unzipped_fmu, "bend_angle", "2.0")
    assert "set 0 step 3 logger_calls 1" in run.stdout  # a refused step: fmi2Error, one message
    assert "bend_angle = 2.0 rad" in run.stdout and "max_bend_angle" in run.stdout
    assert "[UniversalJoint" not in run.stderr  # nothing on stderr


def without_slave_package(copy: Path) -> None:
    for package in (copy / "resources").glob("cardan_joint_*"):
        shutil.rmtree(package)


UNUSABLE = {
    # name: (edit of the record, environment (None: unset), what the message says)
    "user's library missing, home and path given": (
        None,
        {"LIBRARY": "/nowhere/libpython3.11.so.1.0", "HOME": "/nowhere", "PATH": "/nowhere"},
        "cannot load the Python library '/nowhere/libpython3.11.so.1.0'",
    ),
    "user's library without a standard library beside it": (
        None,
        {"LIBRARY": "/nowhere/libpython3.11.so.1.0"},
        "$CARDAN_JOINT_FMU_PYTHON_LIBRARY names /nowhere/libpython3.11.so.1.0, but its",
    ),
    "user's path without the standard library": (
        None,
        {"LIBRARY": "<build>", "HOME": "/", "PATH": "/nowhere:/tmp"},
        "has no standard library (encodings/__init__.py)",
    ),
    "user's library not a Python": (
        None,
        {"LIBRARY": "/lib/x86_64-linux-gnu/libc.so.6", "HOME": "/", "PATH": "<path>"},
        "has no Py_IsInitialized: not a CPython",
    ),
    "record needing a newer Python": (
        lambda text: text.replace("minimum = 3.10", "minimum = 3.99"),
        {},
        "this FMU needs CPython 3.99 or newer, but the Python",
    ),
    "record without its minimum": (
        lambda text: text.replace("minimum = 3.10", ""),
        {},
        "no valid 'minimum'",
    ),
    "record missing": (lambda text: None, {}, "python_runtime.txt (No such file"),
    "slave code that cannot import": (without_slave_package, {}, "No module named"),
}


@pytest.mark.parametrize("case", UNUSABLE)
def test_an_unusable_python_gives_null_and_says_what_to_fix(c_host, unzipped_fmu, tmp_path, case):
    edit, environment, advice = UNUSABLE[case]
    broken = tmp_path / "fmu"
    shutil.copytree(unzipped_fmu, broken)
    record = broken / "resources" / "python_runtime.txt"
    if edit is without_slave_package:
        edit(broken)
    elif edit:
        text = edit(record.read_text())
        record.write_text(text) if text is not None else record.unlink()
    known = {"<build>": shared_libpython(), "<path>": ":".join(search_path())}
    variables = {
        f"CARDAN_JOINT_FMU_PYTHON_{name}": known.get(value, value)
        for name, value in environment.items()
    }
    fatal = edit is without_slave_package  # pythonfmu logs its import error as fatal
    run = run_host(c_host, "instantiate", broken, environment=variables, fatal_logged=fatal)
    assert "instance NULL" in run.stdout
    assert advice in run.stderr and "LOG 3" in run.stderr, run.stderr


def test_the_users_python_is_used_where_the_builds_is_gone(c_host, unzipped_fmu, tmp_path):
    """The record's hint at the build's Python points nowhere (the build machine's
    Python gone); the user's variables name this process's Python through a link of
    their own, and the dynamic linker's log shows that link is the library loaded."""
    gone = "library = /nowhere/libpython3.11.so.1.0\nhome = /nowhere\npath = /nowhere/lib\n"
    moved = fmu_copy_with_record(unzipped_fmu, tmp_path, lambda text: text + gone)
    users = tmp_path / "users_python" / Path(shared_libpython()).name
    users.parent.mkdir()
    users.symlink_to(shared_libpython())
    variables = {
        "CARDAN_JOINT_FMU_PYTHON_LIBRARY": str(users),
        "CARDAN_JOINT_FMU_PYTHON_HOME": sys.base_prefix,
        "CARDAN_JOINT_FMU_PYTHON_PATH": ":".join(search_path()),
        "LD_DEBUG": "files",
    }
    run = run_host(c_host, "instantiate", moved, environment=variables)
    assert "instance ok" in run.stdout, run.stderr
    assert f"file={users} " in run.stderr, "the user's library was not the one loaded"


def test_threads_each_with_an_instance_and_one_instance_on_two_threads(c_host, unzipped_fmu):
    assert "threads ok" in run_host(c_host, "threads", unzipped_fmu, 2000).stdout


def test_two_hundred_instantiate_free_cycles_and_a_clean_exit(c_host, unzipped_fmu):
    assert "cycles 200 ok" in run_host(c_host, "cycles", unzipped_fmu, 200).stdout


def test_call_order_fuzz_every_illegal_call_answered(c_host, unzipped_fmu):
    run = run_host(c_host, "fuzz", unzipped_fmu, 20261123, 10_000)
    assert "fuzz 10000 calls" in run.stdout
    assert "all answered; after reset equal to a fresh instance" in run.stdout


def test_fmpy_and_libcosim_in_a_python_that_links_libpython_statically(fmu_path):
    """/usr/bin/python3.11 has libpython in its executable: the loader must use it."""
    python = Path("/usr/bin/python3.11")
    if not python.exists() or sys.version_info[:2] != (3, 11):
        pytest.skip("needs /usr/bin/python3.11 and a 3.11 build")
    site = next(p for p in sys.path if p.endswith("site-packages"))
    source = str(Path(__file__).resolve().parents[2] / "fmu_src")
    script = (
        "from fmpy import simulate_fmu\n"
        "from cardan_joint.host.cosim import run_libcosim\n"
        f"fmu = {str(fmu_path)!r}\n"
        "r = simulate_fmu(fmu, stop_time=0.5, output_interval=1e-3,"
        " start_values={'input_speed': 12.0, 'bend_angle': 0.4})\n"
        "c = run_libcosim(fmu, 0.5, 1e-3, {'input_speed': 12.0, 'bend_angle': 0.4},"
        " ['output_angle'])\n"
        "print(repr(float(r['output_angle'][-1])), repr(float(c['output_angle'][-1])))\n"
    )
    runs = [
        subprocess.run(
            [executable, "-c", script],
            capture_output=True,
            text=True,
            env={**EMPTY_ENVIRONMENT, "PYTHONPATH": f"{site}:{source}"},
            timeout=120,
        )
        for executable in (str(python), sys.executable)
    ]
    assert all(run.returncode == 0 for run in runs), runs[0].stderr + runs[1].stderr
    assert runs[0].stdout == runs[1].stdout  # unchanged results, bit for bit
    fmpy_angle, libcosim_angle = map(float, runs[0].stdout.split())
    assert fmpy_angle == pytest.approx(libcosim_angle, rel=1e-12)


def test_the_fmu_ships_the_runtime_as_its_only_binary(fmu_path):
    """The runtime constructs and calls the slave itself: no pythonfmu binary."""
    names = zipfile.ZipFile(fmu_path).namelist()
    assert [name for name in names if name.startswith("binaries/")] == [
        "binaries/linux64/UniversalJoint.so"
    ]
    assert "resources/python_runtime.txt" in names


def test_the_fmu_binary_needs_no_cxx_runtime(unzipped_fmu):
    """pythonfmu 0.7.0's binary needed GCC 12's C++ runtime (GLIBCXX_3.4.30): a host
    that brings an older libstdc++ first (MATLAB) could not instantiate the FMU."""
    if not shutil.which("objdump"):
        pytest.skip("needs objdump (binutils)")
    binary = Path(unzipped_fmu) / "binaries" / "linux64" / "UniversalJoint.so"
    symbols = subprocess.run(
        ["objdump", "-T", str(binary)], capture_output=True, text=True, check=True
    ).stdout
    assert "GLIBC_" in symbols  # the table was read
    assert "GLIBCXX" not in symbols and "CXXABI" not in symbols


def test_finding_and_starting_a_python_spawns_no_process(c_host, unzipped_fmu, tmp_path):
    """No ldconfig -p, no python3 -c: a host's fmi2Instantiate must not fork."""
    if not shutil.which("strace"):
        pytest.skip("needs strace to watch the host's system calls")

    def needs_only(text: str) -> str:  # the machine's Python, not the build's
        return "\n".join(line for line in text.splitlines() if line[:7] in ("minimum", "version"))

    without_hint = fmu_copy_with_record(unzipped_fmu, tmp_path, needs_only)
    trace = tmp_path / "trace"
    calls = "trace=execve,execveat,fork,vfork"
    run = subprocess.run(
        ["strace", "-f", "-qq", "-e", calls, "-o", trace, c_host, "instantiate", without_hint],
        capture_output=True,
        text=True,
        env=EMPTY_ENVIRONMENT,
        timeout=120,
    )
    assert "instance ok" in run.stdout, run.stderr  # it found and ran the machine's Python
    (host,) = trace.read_text().splitlines()  # only strace's own execve of the host
    assert f'execve("{c_host}"' in host
