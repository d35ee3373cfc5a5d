"""Issue 33 item 4: two builds of the runtime in one process, today's and one whose
process-wide start object has another layout (the lock moved: compiled with
-DCARDAN_JOINT_PROCESS_LAYOUT_TRIAL): whichever starts second refuses with both
layouts named, and nothing hangs, started one after the other or at once."""

import shutil
import subprocess

import pytest
from test_concurrent_start import fmu_argument

from cardan_joint.fmi.native import compile_loader

TIMEOUT = 60


@pytest.fixture(scope="module")
def trial_fmu(unzipped_fmu, tmp_path_factory):
    """The FMI 2.0 FMU with its runtime built in the trial layout."""
    folder = tmp_path_factory.mktemp("trial_layout") / "fmu"
    shutil.copytree(unzipped_fmu, folder)
    binary = next((folder / "binaries" / "linux64").glob("*.so"))
    with pytest.MonkeyPatch.context() as patch:
        patch.setenv("CC", "cc -DCARDAN_JOINT_PROCESS_LAYOUT_TRIAL")
        compile_loader(binary.stem, binary, 2)
    return folder


def run(concurrent_host, mode, folders):
    return subprocess.run(
        [str(concurrent_host), mode, *map(fmu_argument, folders)],
        env={"PATH": "/usr/bin:/bin"},
        capture_output=True,
        text=True,
        timeout=TIMEOUT,
    )


@pytest.mark.parametrize("trial_first", [False, True], ids=["today-first", "trial-first"])
def test_the_second_layout_in_a_process_is_refused_by_name(
    concurrent_host, fmi3_unzipped, trial_fmu, trial_first
):
    folders = [fmi3_unzipped, trial_fmu][:: -1 if trial_first else 1]
    done = run(concurrent_host, "serial", folders)
    lines = done.stdout.splitlines()
    assert done.returncode == 1 and len(lines) == 2, done.stdout + done.stderr
    assert lines[0].startswith("fmu 0: ") and "returned NULL" not in lines[0]
    assert lines[1] == (
        f"fmu 1: {'fmi3InstantiateCoSimulation' if trial_first else 'fmi2Instantiate'} "
        "returned NULL"
    )
    first, second = (1000, 1) if trial_first else (1, 1000)
    assert f"in layout {first} (" in done.stderr
    assert f"knows layout {second} (" in done.stderr


def test_two_layouts_started_at_once_never_hang(concurrent_host, fmi3_unzipped, trial_fmu):
    for _ in range(3):
        done = run(concurrent_host, "together", [fmi3_unzipped, trial_fmu])
        assert done.returncode == 1 and done.stdout.count("returned NULL") == 1, done.stdout
        assert "another FMU in this process, built by another release" in done.stderr
