"""Issue 24 item 2 (lesser statuses): a C host in the C locale (no LANG, as under
`env -i`) runs an FMU extracted below a folder with a non-ASCII name: the runtime
starts Python in UTF-8 mode. And FMI 3.0's resourcePath is a plain path, not a URI:
a folder named x%41y is not read as xAy."""

import shutil
import subprocess

import pytest

# FMI 2.0's fmuResourceLocation is a URI, in which %41 does mean A.
CASES = [(2, "résumé_ü"), (3, "résumé_ü"), (3, "x%41y")]


@pytest.mark.parametrize("version, folder", CASES)
def test_an_fmu_below_an_unusual_folder_name_instantiates(request, tmp_path, version, folder):
    host = request.getfixturevalue("c_host3" if version == 3 else "c_host")
    unzipped = request.getfixturevalue("fmi3_unzipped" if version == 3 else "unzipped_fmu")
    copy = tmp_path / folder / "fmu"
    shutil.copytree(unzipped, copy)
    run = subprocess.run(
        [str(host), "instantiate", str(copy)],
        env={"PATH": "/usr/bin:/bin"},
        capture_output=True,
        text=True,
        timeout=120,
    )
    assert run.returncode == 0 and "instance ok" in run.stdout, run.stdout + run.stderr
