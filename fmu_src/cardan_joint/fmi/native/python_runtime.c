/* Starting and entering the Python that runs the FMU's slave.
 *
 * A Python host (FMPy, libcosimpy, a statically linked python3) already has
 * one: use it, whatever its 3.x from the record's minimum, never a second
 * interpreter.  A C host has none: load the one find_python names RTLD_GLOBAL
 * (extension modules resolve their symbols in the global scope) and start it
 * isolated from the environment with that home and search path.
 *
 * No Python headers: every function is looked up with dlsym and declared here,
 * so that one loader binary starts CPython 3.10 to 3.13 and any machine with
 * a C compiler builds it.  PyConfig's layout differs between those versions;
 * the legacy Py_SetPythonHome/Py_SetPath/Py_InitializeEx and the Py_*Flag
 * globals, deprecated but exported by all of them, have one ABI.
 */
#define _GNU_SOURCE
#include "loader.h"

#include <dlfcn.h>
#include <limits.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include <wchar.h>

typedef struct _ts PyThreadState;
typedef int PyGILState_STATE;  /* an enum in Python.h */

#define PY_FUNCTIONS(X)                                                                  \
    X(int, Py_IsInitialized, (void)) X(const char *, Py_GetVersion, (void))              \
    X(PyGILState_STATE, PyGILState_Ensure, (void))                                       \
    X(void, PyGILState_Release, (PyGILState_STATE))                                      \
    X(PyThreadState *, PyGILState_GetThisThreadState, (void))                            \
    X(PyThreadState *, PyEval_SaveThread, (void))                                        \
    X(void, PyEval_RestoreThread, (PyThreadState *))                                     \
    X(void, PyThreadState_Clear, (PyThreadState *)) X(void, PyThreadState_DeleteCurrent, (void))
#define PY_INIT_FUNCTIONS(X)                                                             \
    X(void, Py_SetPythonHome, (const wchar_t *)) X(void, Py_SetPath, (const wchar_t *))  \
    X(wchar_t *, Py_DecodeLocale, (const char *, size_t *)) X(void, Py_InitializeEx, (int))
static const char *const INIT_FLAGS[] = {
    "Py_IsolatedFlag", "Py_IgnoreEnvironmentFlag", "Py_NoUserSiteDirectory", "Py_NoSiteFlag"};

#define DECLARE(result, name, parameters) static result(*p_##name) parameters;
PY_FUNCTIONS(DECLARE)
PY_INIT_FUNCTIONS(DECLARE)

static pthread_mutex_t start_lock = PTHREAD_MUTEX_INITIALIZER;
static int python_ready;               /* set once, under start_lock */
static pthread_key_t thread_state_key;
static char in_use[4200] = "no Python";   /* for messages: which Python runs the slave */

const char *python_in_use(void)
{
    return in_use;
}

static void describe(const char *where)
{
    const char *version = p_Py_GetVersion();
    snprintf(in_use, sizeof in_use, "Python %.*s %s", (int)strcspn(version, " "), version, where);
}

#define RESOLVE(result, name, parameters)                                                \
    if (!(*(void **)&p_##name = dlsym(library, #name))) {                                \
        snprintf(error, size, "%s has no %s: not a CPython 3.10 to 3.13", where, #name); \
        return -1;                                                                       \
    }

static int resolve(void *library, const char *where, char *error, size_t size)
{
    PY_FUNCTIONS(RESOLVE)
    return 0;
}

static int resolve_init(void *library, const char *where, char *error, size_t size)
{
    PY_INIT_FUNCTIONS(RESOLVE)
    return 0;
}

/* "3.12.1 (main, ...)": usable from the record's minimum on. */
static int check_version(const struct runtime_record *record, const char *whose,
                         char *error, size_t size)
{
    const char *version = p_Py_GetVersion();
    int major = 0, minor = -1;
    if (sscanf(version, "%d.%d", &major, &minor) == 2 && major == 3 &&
        minor >= record->minimum_minor)
        return 0;
    snprintf(error, size, "this FMU needs CPython 3.%d or newer, but the Python %s is %.*s; "
             "run it in a Python 3.%d to 3.%d process", record->minimum_minor, whose,
             (int)strcspn(version, " "), version, record->minimum_minor, NEWEST_MINOR);
    return -1;
}

/* Py_InitializeEx aborts the process when it cannot import encodings: refuse
 * a search path without it. */
static int has_standard_library(const char *path)
{
    char entries[sizeof ((struct python_location *)0)->path], probe[PATH_MAX];
    snprintf(entries, sizeof entries, "%s", path);
    for (char *save, *entry = strtok_r(entries, ":", &save); entry;
         entry = strtok_r(NULL, ":", &save)) {
        snprintf(probe, sizeof probe, "%s/encodings/__init__.py", entry);
        size_t n = strlen(entry);
        if (access(probe, R_OK) == 0 || (n > 4 && strcmp(entry + n - 4, ".zip") == 0 &&
                                         access(entry, R_OK) == 0))
            return 1;
    }
    return 0;
}

static int start_interpreter(void *library, const struct python_location *python,
                             char *error, size_t size)
{
    if (!has_standard_library(python->path)) {
        snprintf(error, size, "the search path '%s' for Python %s has no standard library "
                 "(encodings/__init__.py); " FIX_HINT, python->path, python->library);
        return -1;
    }
    for (size_t i = 0; i < sizeof INIT_FLAGS / sizeof *INIT_FLAGS; i++) {
        int *flag = dlsym(library, INIT_FLAGS[i]);
        if (!flag) {
            snprintf(error, size, "%s has no %s: not a CPython 3.10 to 3.13", python->library,
                     INIT_FLAGS[i]);
            return -1;
        }
        *flag = 1;  /* isolated: no environment, no user site, no site: the path is all */
    }
    /* The legacy API keeps these pointers: they live as long as the process. */
    wchar_t *home = p_Py_DecodeLocale(python->home, NULL);
    wchar_t *path = p_Py_DecodeLocale(python->path, NULL);
    if (!home || !path) {
        snprintf(error, size, "cannot decode Python's home '%s' or path '%s'", python->home,
                 python->path);
        return -1;
    }
    p_Py_SetPythonHome(home);
    p_Py_SetPath(path);
    p_Py_InitializeEx(0);  /* 0: the host owns its signals */
    if (!p_Py_IsInitialized()) {
        snprintf(error, size, "Python %s did not start with home '%s' and path '%s'; " FIX_HINT,
                 python->library, python->home, python->path);
        return -1;
    }
    p_PyEval_SaveThread();  /* the GIL is free; this thread keeps its main thread state */
    return 0;
}

static int load_and_start(const struct runtime_record *record, char *error, size_t size)
{
    struct python_location python;
    if (find_python(record, &python, error, size))
        return -1;
    void *library = dlopen(python.library, RTLD_NOW | RTLD_GLOBAL);
    if (!library) {
        snprintf(error, size, "cannot load the Python library '%s' (%s); " FIX_HINT,
                 python.library, dlerror());
        return -1;
    }
    if (resolve(library, python.library, error, size) ||
        check_version(record, python.library, error, size) ||
        resolve_init(library, python.library, error, size) ||
        start_interpreter(library, &python, error, size)) {
        dlclose(library);
        return -1;
    }
    char where[sizeof python.library + 8];
    snprintf(where, sizeof where, "from %s", python.library);
    describe(where);
    return 0;
}

/* A host thread without a Python thread state keeps the one it gets here until
 * it exits: pythonfmu's PyGILState_Ensure/Release on every call would otherwise
 * create and destroy one each time, which costs more than the step itself. */
/* At thread exit glibc has already emptied Python's own thread-specific slot
 * (its key is older), so PyGILState_Release would not find the state: end it
 * by hand. */
static void release_thread_state(void *thread_state)
{
    if (p_Py_IsInitialized && p_Py_IsInitialized()) {
        p_PyEval_RestoreThread(thread_state);
        p_PyThreadState_Clear(thread_state);
        p_PyThreadState_DeleteCurrent();
    }
}

void enter_python_thread(void)
{
    static __thread int entered;
    if (entered)
        return;
    entered = 1;
    if (p_PyGILState_GetThisThreadState())
        return;  /* a Python thread, or the one that started Python */
    p_PyGILState_Ensure();
    pthread_setspecific(thread_state_key, p_PyEval_SaveThread());
}

int start_python(const struct runtime_record *record, char *error, size_t size)
{
    int result = 0;
    pthread_mutex_lock(&start_lock);
    if (python_ready) {
        result = check_version(record, "already running in this process", error, size);
    } else {
        void *library = RTLD_DEFAULT;
        int (*running)(void) = (int (*)(void))dlsym(library, "Py_IsInitialized");
        if (running && running()) {
            result = resolve(library, "this process's Python", error, size) ||
                     check_version(record, "of this process", error, size);
            if (result == 0)
                describe("(the host's)");
        } else
            result = load_and_start(record, error, size);
        if (result == 0) {
            pthread_key_create(&thread_state_key, release_thread_state);
            python_ready = 1;
        }
    }
    if (result == 0)
        enter_python_thread();
    pthread_mutex_unlock(&start_lock);
    return result;
}
