"""The runtime sets PyConfig's fields without Python headers (config_layout.h): each
CPython minor's offsets there must be those of its own headers."""

import subprocess
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
    for (size_t i = 0; i < N_CONFIG_LAYOUTS; i++) {
        const struct config_layout *l = &CONFIG_LAYOUTS[i];
        if (l->minor != PY_MINOR_VERSION)
            continue;
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


@pytest.mark.parametrize("minor", ["3.10", "3.11", "3.12", "3.13"])
def test_the_layout_table_matches_the_minors_headers(minor, tmp_path):
    headers = minors().get(minor)
    if headers is None:
        pytest.skip(f"no CPython {minor} headers under {PYENV}")
    source = tmp_path / "layout.c"
    source.write_text(PROGRAM)
    program = tmp_path / "layout"
    subprocess.run(
        [*compiler(), f"-I{headers}", f"-I{NATIVE}", str(source), "-o", str(program)], check=True
    )
    assert subprocess.run([str(program)], capture_output=True, text=True).stdout == "layout ok\n"
