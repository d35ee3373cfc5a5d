"""Issue 33 item 2: a C host that holds a Python of its own
(tests/c_host/embedding/embedding.c), FMI 2.0 and 3.0. One libpython loaded and
not running, in either scope, or finalized by the host, is the one the runtime
starts; a plugin's RTLD_LOCAL Python that runs is joined, and the host's Python
works after; a Python the host finalizes under the runtime gives Error or NULL
with a message. Never a second libpython, never a signal. The host's Python is
Debian's debug CPython (python3.11-dbg), which discovery alone would never pick:
a second library beside it is what crashed these hosts."""

import subprocess
from pathlib import Path

import pytest
from c_host.compile import HERE, NATIVE, compile_command
from fmpy import read_model_description

HOST_PYTHON = Path("/usr/lib/x86_64-linux-gnu/libpython3.11d.so.1.0")


@pytest.fixture(scope="module")
def embedding_host(tmp_path_factory) -> Path:
    output = tmp_path_factory.mktemp("embedding") / "embedding"
    source = HERE / "embedding" / "embedding.c"
    subprocess.run(compile_command(output, NATIVE, [source]), check=True)
    return output


def run_embedding(host, mode, folder, version, *extra):
    description = read_model_description(str(folder))
    platform = "linux64" if version == 2 else "x86_64-linux"
    binary = folder / "binaries" / platform / f"{description.coSimulation.modelIdentifier}.so"
    token = description.guid if version == 2 else description.instantiationToken
    arguments = [str(version), str(binary), (folder / "resources").as_uri(), token, *extra]
    return subprocess.run(
        [str(host), mode, *arguments],
        env={"PATH": "/usr/bin:/bin"},
        capture_output=True,
        text=True,
        timeout=120,
    )


@pytest.fixture(params=[2, 3], ids=["fmi2", "fmi3"])
def fmu(request, unzipped_fmu, fmi3_unzipped):
    return request.param, Path(unzipped_fmu if request.param == 2 else fmi3_unzipped)


def test_calls_after_the_host_finalized_python_are_errors_with_a_message(embedding_host, fmu):
    version, folder = fmu
    run = run_embedding(embedding_host, "finalize-after", folder, version)
    assert run.returncode == 0, run.stdout + run.stderr[-2000:]
    assert run.stdout.splitlines() == [
        "step before: 0",
        "finalized: 0",
        "step after: 3",
        "instantiate after: NULL",
        "free after: done",
    ]
    assert "is not running any more (the host finalized it)" in run.stderr
    assert "Python 3." in run.stderr


@pytest.mark.parametrize("mode", ["loaded-global", "loaded-local", "finalized", "running-local"])
def test_the_hosts_own_python_is_the_one_the_fmu_runs_in(embedding_host, fmu, mode):
    assert HOST_PYTHON.is_file(), f"{HOST_PYTHON} is missing: apt-get install python3.11-dbg"
    version, folder = fmu
    run = run_embedding(embedding_host, mode, folder, version, str(HOST_PYTHON))
    assert run.returncode == 0, run.stdout + run.stderr[-2000:]
    lines = run.stdout.splitlines()
    assert lines[:2] == ["instance: ok", "steps: 0"], run.stdout + run.stderr[-2000:]
    if mode == "running-local":
        assert lines[2:] == ["host python: 0"]


def test_two_libpythons_in_the_host_are_refused_by_name(embedding_host, fmu):
    version, folder = fmu
    machines = Path("/usr/lib/x86_64-linux-gnu/libpython3.11.so.1.0")
    both = f"{machines}:{HOST_PYTHON}"
    run = run_embedding(embedding_host, "loaded-local", folder, version, both)
    assert run.returncode == 0, run.stdout + run.stderr[-2000:]
    assert run.stdout.splitlines()[0] == "instance: NULL"
    assert "already holds 2 Python libraries" in run.stderr
    assert str(machines) in run.stderr and str(HOST_PYTHON) in run.stderr
