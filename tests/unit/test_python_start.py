"""Starting a CPython from 3.14 on (python_start.c, PEP 741's PyInitConfig API):
every entry of the search path reaches `module_search_paths`, however many. The
runtime is compiled against a stand-in of the API that prints what it was given,
so no Python 3.14 is needed."""

import subprocess
from pathlib import Path

from cardan_joint.fmi.native import compiler

NATIVE = Path(__file__).resolve().parents[2] / "fmu_src" / "cardan_joint" / "fmi" / "native"
# PEP 741's functions as the start looks them up (dlsym on the library's handle:
# here the program itself), and a host that starts "CPython 3.14" with a path.
STAND_IN = r"""
#include "loader.h"
#include <dlfcn.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

static size_t given;
static char last[256];
static int config;
void *PyInitConfig_Create(void) { return &config; }
void PyInitConfig_Free(void *c) { (void)c; }
int PyInitConfig_GetError(void *c, const char **message)
{
    (void)c;
    *message = "stand-in";
    return 1;
}
int PyInitConfig_SetInt(void *c, const char *name, int64_t value)
{
    (void)c, (void)name, (void)value;
    return 0;
}
int PyInitConfig_SetStr(void *c, const char *name, const char *value)
{
    (void)c, (void)name, (void)value;
    return 0;
}
int PyInitConfig_SetStrList(void *c, const char *name, size_t n, char *const *items)
{
    (void)c, (void)name;
    given = n;
    snprintf(last, sizeof last, "%s", n ? items[n - 1] : "");
    return 0;
}
int Py_InitializeFromInitConfig(void *c) { (void)c; return 0; }

int main(int argc, char **argv)
{
    static struct python_location python = {"libpython3.14-stand-in.so", "/stand-in", ""};
    size_t at = (size_t)snprintf(python.path, sizeof python.path, "%s", argv[1]);
    for (int k = 0; k < atoi(argv[2]); k++)
        at += (size_t)snprintf(python.path + at, sizeof python.path - at, ":/entry/%d", k);
    char error[4096] = "";
    int started = start_interpreter(dlopen(NULL, RTLD_NOW), 14, &python, error, sizeof error);
    printf("%d %zu %s %s\n", started, given, last, error);
    return 0;
}
"""


def test_every_search_path_entry_reaches_python_314s_configuration(tmp_path):
    standard_library = tmp_path / "lib"
    (standard_library / "encodings").mkdir(parents=True)
    (standard_library / "encodings" / "__init__.py").write_text("")
    source, program = tmp_path / "stand_in.c", tmp_path / "stand_in"
    source.write_text(STAND_IN)
    subprocess.run(
        [
            *compiler(),
            "-std=gnu11",
            f"-I{NATIVE}",
            str(NATIVE / "python_start.c"),
            str(source),
            "-rdynamic",
            "-ldl",
            "-o",
            str(program),
        ],
        check=True,
    )
    for entries in (3, 300, 1000):
        run = subprocess.run(
            [str(program), str(standard_library), str(entries)],
            capture_output=True,
            text=True,
            check=True,
        )
        assert run.stdout == f"0 {entries + 1} /entry/{entries - 1} \n"
