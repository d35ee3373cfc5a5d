"""The FMU in a C host, loaded as an FMI tool loads it: dlopen RTLD_LOCAL, empty
environment, no Python of its own (tests/c_host/host.c, compiled here with cc)."""

import shutil
import subprocess
import sys
import zipfile
from pathlib import Path

import numpy as np
import pytest
from c_host.compile import compile_host

EMPTY_ENVIRONMENT = {"PATH": "/usr/bin:/bin"}


@pytest.fixture(scope="session")
def c_host(tmp_path_factory):
    return compile_host(tmp_path_factory.mktemp("c_host") / "host")


def run_host(c_host, *args, timeout=120):
    """The host's run, which must end cleanly (no crash, no abort at exit)."""
    run = subprocess.run(
        [str(c_host), *map(str, args)],
        env=EMPTY_ENVIRONMENT,
        capture_output=True,
        text=True,
        timeout=timeout,
    )
    assert run.returncode == 0, run.stdout[-2000:] + run.stderr[-2000:]
    assert "Fatal" not in run.stderr and "free()" not in run.stderr, run.stderr[-2000:]
    return run


def fmu_copy_with_record(unzipped_fmu, tmp_path, edit):
    """An extracted copy of the FMU whose resources/python_runtime.txt `edit` rewrites."""
    copy = tmp_path / "fmu"
    shutil.copytree(unzipped_fmu, copy)
    record = copy / "resources" / "python_runtime.txt"
    record.write_text(edit(record.read_text()))
    return copy


def test_c_host_equals_fmpy_over_ten_thousand_steps(c_host, fmu_path, unzipped_fmu):
    from fmpy import simulate_fmu

    steps, dt = 10_000, 1e-3
    settings = {
        "input_speed": 40.0,
        "input_acceleration": 3.0,
        "bend_angle": 0.4,
        "bend_angle_rate": 0.01,
        "load_torque": 50.0,
        "yoke_phase": 0.3,
    }
    run = run_host(
        c_host,
        "run",
        unzipped_fmu,
        steps,
        dt,
        *(f"{name}={value!r}" for name, value in settings.items()),
    )
    names = run.stdout.splitlines()[0].replace('"', "").split(",")
    ours = np.loadtxt(run.stdout.splitlines()[1:], delimiter=",")
    theirs = simulate_fmu(
        str(fmu_path), stop_time=steps * dt, output_interval=dt, start_values=settings
    )
    assert ours.shape == (len(theirs), len(names)) and len(theirs) == steps + 1
    for column, name in enumerate(names):
        np.testing.assert_allclose(ours[:, column], theirs[name], rtol=1e-12, atol=0, err_msg=name)


def test_a_bad_input_with_logging_off_reaches_the_logger_once(c_host, unzipped_fmu):
    run = run_host(c_host, "bad", unzipped_fmu, "bend_angle", "2.0")
    assert "set 0 step 2 logger_calls 1" in run.stdout  # fmi2Discard, one message
    assert "bend_angle = 2.0 rad" in run.stdout and "max_bend_angle" in run.stdout
    assert "[UniversalJoint" not in run.stderr  # nothing on stderr


@pytest.mark.parametrize(
    "edit, advice",
    [
        (
            lambda text: text.replace("library = ", "library = /nowhere"),
            "cannot load the Python library",
        ),
        (lambda text: text.replace("version = ", "version = 9"), "built for Python 9"),
        (
            lambda text: "\n".join(
                line for line in text.splitlines() if "site-packages" not in line
            ),
            "numpy cannot be imported",
        ),
    ],
    ids=["library moved", "other minor version", "numpy missing"],
)
def test_an_unusable_python_gives_null_and_says_what_to_fix(
    c_host, unzipped_fmu, tmp_path, edit, advice
):
    broken = fmu_copy_with_record(unzipped_fmu, tmp_path, edit)
    run = run_host(c_host, "instantiate", broken)
    assert "instance NULL logger_calls 1" in run.stdout
    assert advice in run.stderr and "LOG 3" in run.stderr


def test_the_record_can_be_overridden_from_the_environment(c_host, unzipped_fmu, tmp_path):
    broken = fmu_copy_with_record(
        unzipped_fmu, tmp_path, lambda text: text.replace("library = ", "library = /nowhere")
    )
    library = next(
        line.split("=", 1)[1].strip()
        for line in (Path(unzipped_fmu) / "resources" / "python_runtime.txt")
        .read_text()
        .splitlines()
        if line.startswith("library")
    )
    run = subprocess.run(
        [str(c_host), "instantiate", str(broken)],
        capture_output=True,
        text=True,
        env={**EMPTY_ENVIRONMENT, "CARDAN_JOINT_FMU_PYTHON_LIBRARY": library},
    )
    assert run.returncode == 0 and "instance ok" in run.stdout, run.stderr


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
    source = str(Path(__file__).resolve().parents[1] / "fmu_src")
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


def test_the_fmu_ships_the_loader_and_pythonfmus_binary(fmu_path):
    names = zipfile.ZipFile(fmu_path).namelist()
    assert {
        "binaries/linux64/UniversalJoint.so",
        "binaries/linux64/UniversalJoint_pythonfmu.so",
        "resources/python_runtime.txt",
    } <= set(names)
