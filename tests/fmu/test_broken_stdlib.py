"""Issue 24 item 2: a standard library that is there but broken (a syntax error in
encodings/__init__.py, its codec modules missing) makes instantiate return NULL with a
logger message; the C host exits normally (Py_InitializeEx would have exited it)."""

import shutil
import subprocess
from pathlib import Path

import pytest

PYTHON = Path("/root/.pyenv/versions/3.12.1")
LIBRARY = PYTHON / "lib" / "libpython3.12.so.1.0"
STDLIB = PYTHON / "lib" / "python3.12"


def break_syntax(encodings: Path) -> None:
    init = encodings / "__init__.py"
    init.write_text("def (:\n" + init.read_text())


def drop_codecs(encodings: Path) -> None:
    for codec in ("utf_8.py", "ascii.py", "latin_1.py"):
        (encodings / codec).unlink()


@pytest.mark.parametrize("damage", [break_syntax, drop_codecs])
@pytest.mark.parametrize("version", [2, 3])
def test_a_broken_standard_library_is_a_null_instance_and_a_message(
    request, tmp_path, damage, version
):
    if not LIBRARY.exists():
        pytest.skip(f"needs {LIBRARY}")
    host = request.getfixturevalue("c_host3" if version == 3 else "c_host")
    fmu = request.getfixturevalue("fmi3_unzipped" if version == 3 else "unzipped_fmu")
    shadow = tmp_path / "shadow"
    shutil.copytree(STDLIB / "encodings", shadow / "encodings")
    damage(shadow / "encodings")
    environment = {
        "PATH": "/usr/bin:/bin",
        "CARDAN_JOINT_FMU_PYTHON_LIBRARY": str(LIBRARY),
        "CARDAN_JOINT_FMU_PYTHON_HOME": str(PYTHON),
        "CARDAN_JOINT_FMU_PYTHON_PATH": f"{shadow}:{STDLIB}:{STDLIB / 'lib-dynload'}",
    }
    run = subprocess.run(
        [str(host), "instantiate", str(fmu)],
        env=environment,
        capture_output=True,
        text=True,
        timeout=60,
    )
    assert run.returncode == 0, run.stdout + run.stderr
    assert "instance NULL" in run.stdout, run.stdout + run.stderr
    assert "did not start" in run.stderr and "codec" in run.stderr, run.stderr
    assert "Fatal Python error" not in run.stderr
