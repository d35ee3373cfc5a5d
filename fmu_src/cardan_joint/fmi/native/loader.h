/* Shared declarations of the FMU's native loader (see loader.c). */
#ifndef CARDAN_JOINT_LOADER_H
#define CARDAN_JOINT_LOADER_H

#define PY_SSIZE_T_CLEAN
#include <Python.h>
#include <stddef.h>

#define RUNTIME_RECORD "python_runtime.txt"
#define ENV_LIBRARY "CARDAN_JOINT_FMU_PYTHON_LIBRARY"
#define ENV_HOME "CARDAN_JOINT_FMU_PYTHON_HOME"
#define ENV_PATH "CARDAN_JOINT_FMU_PYTHON_PATH"
#define ENV_STDERR "CARDAN_JOINT_FMU_STDERR"
#define FIX_HINT                                                                    \
    "fix the 'library', 'home' and 'path' lines of resources/" RUNTIME_RECORD       \
    " or set $" ENV_LIBRARY ", $" ENV_HOME " and $" ENV_PATH                        \
    " to a Python " PY_MAJOR_MINOR " with numpy"
#define PY_STR_(x) #x
#define PY_STR(x) PY_STR_(x)
#define PY_MAJOR_MINOR PY_STR(PY_MAJOR_VERSION) "." PY_STR(PY_MINOR_VERSION)

/* What the build recorded in resources/python_runtime.txt, after the user's
 * environment overrides. */
struct runtime_record {
    char version[16];      /* major.minor of the build's Python */
    char library[4096];    /* the build's libpython, for hosts without Python */
    char home[4096];       /* sys.base_prefix */
    char executable[4096]; /* the build's interpreter, for sys.executable */
    char path[16384];      /* module search path, ':'-separated */
};

#define MAX_FIXED 64
struct fixed_parameters {
    struct fixed_parameter {
        unsigned vr;
        char name[64];
    } parameters[MAX_FIXED];
    int count;
};
int read_fixed_parameters(const char *resources, struct fixed_parameters *fixed);

/* Resources folder from fmuResourceLocation (a file URI or a plain path). */
int resources_folder(const char *location, char *folder, size_t size);
int read_runtime_record(const char *resources, struct runtime_record *record,
                        char *error, size_t size);

int start_python(const struct runtime_record *record, char *error, size_t size);
void enter_python_thread(void);

#endif
