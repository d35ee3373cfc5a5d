"""The runtime sets PyConfig's fields without Python headers (config_layout.h): each
CPython minor's offsets there must be those of its own headers. The running
Python's own headers (Debian: python3.X-dev) are always checked; pyenv's other
minors where they are installed. Minors from 3.14 on start by option names
(PEP 741) and have no offsets to check."""

import subprocess
import sys
import sysconfig
from pathlib import Path

import pytest

from cardan_joint.fmi.native import compiler

NATIVE = Path(__file__).resolve().parents[2] / "fmu_src" / "cardan_joint" / "fmi" / "native"
PYENV = Path("/root/.pyenv/versions")
PROGRAM = r"""
#include <Python.h>
#include <stdio.h>
#include "config_layout.h"
int main(void)
{
    for (size_t i = 0; i < N_CPYTHON_MINORS; i++) {
        const struct cpython_minor *l = &CPYTHON_MINORS[i];
        if (l->minor != PY_MINOR_VERSION)
            continue;
        if (l->api != CONFIG_STRUCT) {
            puts(PY_MINOR_VERSION >= 14 ? "by names" : "by names too early");
            return 0;
        }
        int ok = l->size == sizeof(PyConfig) && sizeof(PyConfig) <= CONFIG_ROOM &&
                 l->home == offsetof(PyConfig, home) &&
                 l->module_search_paths_set == offsetof(PyConfig, module_search_paths_set) &&
                 l->module_search_paths == offsetof(PyConfig, module_search_paths) &&
                 l->site_import == offsetof(PyConfig, site_import) &&
                 l->install_signal_handlers == offsetof(PyConfig, install_signal_handlers);
        ok = ok && PRECONFIG_SIZE == sizeof(PyPreConfig) &&
             PRECONFIG_UTF8_MODE == offsetof(PyPreConfig, utf8_mode);
        puts(ok ? "layout ok" : "layout differs");
        return 0;
    }
    puts("no layout");
    return 0;
}
"""


def minors():
    found = {}
    for version in sorted(PYENV.glob("3.1[0-9]*")):
        minor = ".".join(version.name.split(".")[:2])
        if (version / "include" / f"python{minor}" / "Python.h").exists():
            found[minor] = version / "include" / f"python{minor}"
    return found


def layout_check(headers: Path, tmp_path: Path) -> str:
    source = tmp_path / "layout.c"
    source.write_text(PROGRAM)
    program = tmp_path / "layout"
    subprocess.run(
        [*compiler(), f"-I{headers}", f"-I{NATIVE}", str(source), "-o", str(program)], check=True
    )
    return subprocess.run([str(program)], capture_output=True, text=True).stdout


def test_the_running_pythons_minor_is_in_the_table_with_its_headers_offsets(tmp_path):
    headers = Path(sysconfig.get_path("include"))
    assert (headers / "Python.h").is_file(), (
        f"no {headers}/Python.h: install the running Python's headers "
        f"(Debian: apt-get install python{sys.version_info.major}.{sys.version_info.minor}-dev)"
    )
    assert layout_check(headers, tmp_path) in ("layout ok\n", "by names\n")


@pytest.mark.parametrize("minor", ["3.10", "3.11", "3.12", "3.13"])
def test_the_layout_table_matches_the_minors_headers(minor, tmp_path):
    headers = minors().get(minor)
    if headers is None:
        pytest.skip(f"no CPython {minor} headers under {PYENV}")
    assert layout_check(headers, tmp_path) == "layout ok\n"
