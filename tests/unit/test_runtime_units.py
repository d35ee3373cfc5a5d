"""Parts of the native runtime, each compiled alone with a small C program that
stands in for what it is given (no FMU, no Python of the minor in question):

- starting a CPython from 3.14 on (python_start.c, PEP 741's PyInitConfig API):
  every entry of the search path reaches `module_search_paths`, however many;
- FMI 3's table of value references (fast_references.c's `fast_table`): a table
  whose starts or indices fall outside it or the arrays is refused."""

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


def build(tmp_path: Path, name: str, program_text: str, *sources: str) -> Path:
    """`program_text` compiled with the runtime's `sources` into tmp_path/name."""
    source, program = tmp_path / f"{name}.c", tmp_path / name
    source.write_text(program_text)
    subprocess.run(
        [
            *compiler(),
            "-std=gnu11",
            '-DMODEL_IDENTIFIER="stand_in"',
            f"-I{NATIVE}",
            *(str(NATIVE / s) for s in sources),
            str(source),
            "-rdynamic",
            "-ldl",
            "-o",
            str(program),
        ],
        check=True,
    )
    return program


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


# fast_table on the tables of argv (comma-separated int64s each): 1 taken, 0 refused,
# for arrays of 3 known values and 2 outputs (flat indices 0 to 4).
TABLES = r"""
#define _GNU_SOURCE
#include "fast_path.h"
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* fast_references.c's check of the layout reports; the tables' check does not. */
void reportf(struct instance *in, fmi2Status status, const char *format, ...)
{
    (void)in, (void)status, (void)format;
}

int main(int argc, char **argv)
{
    for (int k = 1; k < argc; k++) {
        long long table[64];
        size_t n = 0;
        for (char *save, *item = strtok_r(argv[k], ",", &save); item && n < 64;
             item = strtok_r(NULL, ",", &save))
            table[n++] = atoll(item);
        struct fast_path fast = {.known_size = 3, .first_output = 3, .outputs = 2};
        printf("%d", fast_table(&fast, (const char *)table, n * sizeof *table));
        free(fast.table);
    }
    puts("");
    return 0;
}
"""


def test_a_table_of_value_references_outside_itself_or_the_arrays_is_refused(tmp_path):
    program = build(tmp_path, "tables", TABLES, "fast_references.c", "python_api.c")
    tables = {
        "2,0,1,3,0,3,4": 1,  # reference 0: index 0; reference 1: indices 3 and 4
        "2,0,0,2,1,2": 1,  # reference 0 has no index (FMI 3's time)
        "2,0,1,3,0,3,5": 0,  # index 5 is past the arrays
        "2,0,1,3,0,-1,4": 0,  # a negative index
        "2,1,1,3,0,3,4": 0,  # the first reference starts past the first index
        "2,0,9,3,0,3,4": 0,  # reference 0 would read 9 indices of 3
        "2,0,-4,3,0,3,4": 0,  # reference 1 would start before the table's indices
        "3,0,2,1,3,0,3,4": 0,  # starts that go back
        "2,0,1,4,0,3,4": 0,  # the last start is not the count of indices
        "0,0": 0,  # no reference
    }
    run = subprocess.run([str(program), *tables], capture_output=True, text=True, check=True)
    assert run.stdout.strip() == "".join(str(taken) for taken in tables.values())
