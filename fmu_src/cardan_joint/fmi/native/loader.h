/* Shared declarations of the FMU's native loader (see loader.c). */
#ifndef CARDAN_JOINT_LOADER_H
#define CARDAN_JOINT_LOADER_H

#include <stddef.h>

#define RUNTIME_RECORD "python_runtime.txt"
/* Each variable: value reference, type, size, fixed (0/1), name (native/__init__.py). */
#define VARIABLES_RECORD "variables.txt"
#define ENV_LIBRARY "CARDAN_JOINT_FMU_PYTHON_LIBRARY"
#define ENV_HOME "CARDAN_JOINT_FMU_PYTHON_HOME"
#define ENV_PATH "CARDAN_JOINT_FMU_PYTHON_PATH"
#define ENV_STDERR "CARDAN_JOINT_FMU_STDERR"
#define ENV_PYTHON_STEP "CARDAN_JOINT_FMU_PYTHON_STEP"
/* The CPython minors the loader starts are config_layout.h's table; a Python
 * host of any 3.x from the record's minimum is joined. */
#define FIX_HINT                                                                    \
    "install a CPython 3 with its shared library (e.g. Debian's libpython3.11), "   \
    "or point the FMU at one: $" ENV_LIBRARY "=<its libpython3.X.so.1.0>, "         \
    "and if its standard library is not at <prefix>/lib/python3.X, $" ENV_HOME     \
    "=<prefix> and $" ENV_PATH "=<':'-separated module search path>"

/* One Python as the loader would start it. */
struct python_location {
    char library[4096]; /* libpython3.X.so.1.0 */
    char home[4096];    /* sys.base_prefix; derived from the library if empty */
    char path[16384];   /* module search path, ':'-separated; derived if empty */
};

/* What resources/python_runtime.txt says the FMU needs, and the user's
 * environment overrides. */
struct runtime_record {
    int minimum_minor;            /* 3.<minimum_minor> or newer */
    int build_minor;              /* the build's 3.x: preferred among the machine's */
    struct python_location build; /* optional hint: the build's Python, if still there */
    struct python_location user;  /* $CARDAN_JOINT_FMU_PYTHON_* */
};

/* One row of resources/VARIABLES_RECORD; `keep` returns 0 for a row it cannot keep. */
struct record_row {
    unsigned vr;
    char type[16];
    size_t size;
    int fixed;
    char name[64];
};
int read_variable_record(const char *resources, int (*keep)(const struct record_row *, void *),
                         void *kept, int most, char *error, size_t size);
/* For messages: the name of the variable with value reference vr (0), else -1. */
int variable_name(const char *resources, unsigned vr, char *name, size_t size);

#define MAX_FIXED 64
struct fixed_parameters {
    struct fixed_parameter {
        unsigned vr;
        char name[64];
    } parameters[MAX_FIXED];
    int count;
};
int read_fixed_parameters(const char *resources, struct fixed_parameters *fixed,
                          char *error, size_t size);

/* Resources folder from fmuResourceLocation (a file URI or a plain path). */
int resources_folder(const char *location, char *folder, size_t size);
int read_runtime_record(const char *resources, struct runtime_record *record,
                        char *error, size_t size);

/* The Python to start in a process without one: the user's, the build's if still
 * there, else the machine's (python_discovery.c). 0, or -1 with what was looked at. */
int find_python(const struct runtime_record *record, struct python_location *found,
                char *error, size_t size);
/* The Python already loaded at `library` (the one in the process, not running):
 * with the user's home and path, else those beside it; 0, or -1 and why. */
int locate_loaded(const struct runtime_record *record, const char *library,
                  struct python_location *found, char *error, size_t size);
/* How many libpython3.X are loaded in this process, in any scope: the first's
 * path in `one`, all of them in `names` (python_present.c). */
int loaded_pythons(char *one, size_t one_size, char *names, size_t names_size);
/* FMI-version-neutral: find or start the Python, enter it on this thread. */
int start_python(const struct runtime_record *record, char *error, size_t size);
/* 0, or -1 when the process's Python is not running any more (the host finalized it). */
int enter_python_thread(void);
/* Py_InitializeFromConfig with that home and path (python_start.c): 0, -1 when it
 * was not tried (the process can try another Python), -2 when it failed. */
int start_interpreter(void *library, int minor, const struct python_location *python,
                      char *error, size_t size);
const char *python_in_use(void);  /* "Python 3.12.1 from <library>", for messages */

#endif
