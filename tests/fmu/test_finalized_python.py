"""Issue 33 item 2: a C host that finalizes the Python the runtime started in it
(tests/c_host/finalize/finalize.c) gets Error or NULL with a message from every
later call, FMI 2.0 and 3.0, and ends normally: never a signal."""

import subprocess
from pathlib import Path

import pytest
from c_host.compile import HERE, NATIVE, compile_command
from fmpy import read_model_description


@pytest.fixture(scope="module")
def finalize_host(tmp_path_factory) -> Path:
    output = tmp_path_factory.mktemp("finalize") / "finalize"
    subprocess.run(compile_command(output, NATIVE, [HERE / "finalize" / "finalize.c"]), check=True)
    return output


@pytest.mark.parametrize("version", [2, 3])
def test_calls_after_the_host_finalized_python_are_errors_with_a_message(
    finalize_host, unzipped_fmu, fmi3_unzipped, version
):
    folder = Path(unzipped_fmu if version == 2 else fmi3_unzipped)
    description = read_model_description(str(folder))
    platform = "linux64" if version == 2 else "x86_64-linux"
    binary = folder / "binaries" / platform / f"{description.coSimulation.modelIdentifier}.so"
    token = description.guid if version == 2 else description.instantiationToken
    run = subprocess.run(
        [str(finalize_host), str(version), str(binary), (folder / "resources").as_uri(), token],
        env={"PATH": "/usr/bin:/bin"},
        capture_output=True,
        text=True,
        timeout=120,
    )
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
