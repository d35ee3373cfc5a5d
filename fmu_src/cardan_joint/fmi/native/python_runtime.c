/* Finding, starting and entering the Python that runs the FMU's slave.
 *
 * A C host has no Python: load the build's libpython RTLD_GLOBAL (extension
 * modules such as numpy resolve their symbols in the global scope) and start
 * it isolated from the environment with the home and search path the build
 * recorded.  A Python host (FMPy, libcosimpy, a statically linked python3)
 * already has one: use it, never a second interpreter.
 *
 * Every Python function is looked up with dlsym: the loader links no
 * libpython, so that it loads in any host.  Python.h is used for types only.
 */
#define _GNU_SOURCE
#include "loader.h"

#include <dlfcn.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define PY_FUNCTIONS(X)                                                          \
    X(Py_IsInitialized) X(Py_GetVersion) X(PyGILState_Ensure)                    \
    X(PyGILState_Release) X(PyGILState_GetThisThreadState) X(PyEval_SaveThread)  \
    X(PyEval_RestoreThread) X(PyImport_ImportModule) X(PyErr_Fetch)              \
    X(PyErr_NormalizeException) X(PyObject_Str) X(PyUnicode_AsUTF8)             \
    X(Py_DecRef) X(PyThreadState_Clear) X(PyThreadState_DeleteCurrent)
#define PY_INIT_FUNCTIONS(X)                                                     \
    X(PyConfig_InitIsolatedConfig) X(PyConfig_SetBytesString) X(PyConfig_Clear)  \
    X(PyWideStringList_Append) X(Py_DecodeLocale) X(PyMem_RawFree)              \
    X(Py_InitializeFromConfig) X(PyStatus_Exception)

#define DECLARE(name) static __typeof__(&name) p_##name;
PY_FUNCTIONS(DECLARE)
PY_INIT_FUNCTIONS(DECLARE)

static pthread_mutex_t start_lock = PTHREAD_MUTEX_INITIALIZER;
static int python_ready;               /* set once, under start_lock */
static char numpy_checked_for[sizeof ((struct runtime_record *)0)->path];   /* the search path numpy was found with */
static pthread_key_t thread_state_key;

static int resolve(void *library, char *error, size_t size)
{
#define RESOLVE(name)                                                                \
    if (!(p_##name = (__typeof__(&name))dlsym(library, #name))) {                    \
        snprintf(error, size, "the Python library has no %s: not a CPython %s", #name, \
                 PY_VERSION);                                                        \
        return -1;                                                                   \
    }
    PY_FUNCTIONS(RESOLVE)
    return 0;
}

static int resolve_init(void *library, char *error, size_t size)
{
    PY_INIT_FUNCTIONS(RESOLVE)
    return 0;
#undef RESOLVE
}

/* "3.11.7 (main, ...)" is usable by an FMU built for "3.11". */
static int version_matches(const char *running, const char *built)
{
    size_t n = strlen(built);
    return strncmp(running, built, n) == 0 && running[n] == '.';
}

static void set_string(PyConfig *config, wchar_t **field, const char *value)
{
    if (value && *value)
        p_PyConfig_SetBytesString(config, field, value);
}

static int start_interpreter(const struct runtime_record *record, char *error, size_t size)
{
    PyConfig config;
    p_PyConfig_InitIsolatedConfig(&config);
    config.install_signal_handlers = 0;    /* the host owns its signals */
    config.site_import = 0;                /* the recorded path is the whole path */
    config.parse_argv = 0;
    set_string(&config, &config.home, record->home);
    set_string(&config, &config.program_name, record->executable);
    config.module_search_paths_set = 1;
    char paths[sizeof record->path];
    strcpy(paths, record->path);
    for (char *save, *entry = strtok_r(paths, ":", &save); entry;
         entry = strtok_r(NULL, ":", &save)) {
        wchar_t *wide = p_Py_DecodeLocale(entry, NULL);
        if (wide) {
            p_PyWideStringList_Append(&config.module_search_paths, wide);
            p_PyMem_RawFree(wide);
        }
    }
    PyStatus status = p_Py_InitializeFromConfig(&config);
    p_PyConfig_Clear(&config);
    if (p_PyStatus_Exception(status)) {
        snprintf(error, size,
                 "Python at %s did not start (%s: %s) with home %s and path %s; " FIX_HINT,
                 record->library, status.func ? status.func : "init",
                 status.err_msg ? status.err_msg : "unknown error", record->home, record->path);
        return -1;
    }
    p_PyEval_SaveThread();  /* the GIL is free; this thread keeps its main thread state */
    return 0;
}

static void describe_python_error(char *text, size_t size)
{
    PyObject *type = NULL, *value = NULL, *traceback = NULL;
    p_PyErr_Fetch(&type, &value, &traceback);
    p_PyErr_NormalizeException(&type, &value, &traceback);
    PyObject *string = value ? p_PyObject_Str(value) : NULL;
    const char *utf8 = string ? p_PyUnicode_AsUTF8(string) : NULL;
    snprintf(text, size, "%s", utf8 ? utf8 : "unknown error");
    PyObject *owned[] = {string, type, value, traceback};
    for (size_t i = 0; i < sizeof owned / sizeof *owned; i++)
        if (owned[i])
            p_Py_DecRef(owned[i]);
}

static int check_numpy(const struct runtime_record *record, char *error, size_t size)
{
    if (strcmp(numpy_checked_for, record->path) == 0)
        return 0;
    PyGILState_STATE gil = p_PyGILState_Ensure();
    PyObject *numpy = p_PyImport_ImportModule("numpy");
    char reason[512] = "";
    if (numpy)
        p_Py_DecRef(numpy);
    else
        describe_python_error(reason, sizeof reason);
    p_PyGILState_Release(gil);
    if (!numpy) {
        snprintf(error, size,
                 "numpy cannot be imported by Python %.20s (%s); install numpy into that Python "
                 "(python -m pip install numpy) or add the site-packages folder that has it to "
                 "the 'path' line of resources/" RUNTIME_RECORD " or to $" ENV_PATH,
                 p_Py_GetVersion(), reason);
        return -1;
    }
    snprintf(numpy_checked_for, sizeof numpy_checked_for, "%s", record->path);
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

static int check_version(const struct runtime_record *record, const char *whose,
                         char *error, size_t size)
{
    if (version_matches(p_Py_GetVersion(), record->version))
        return 0;
    snprintf(error, size,
             "this FMU was built for Python %s but the Python %s is %.20s; run it in a "
             "Python %s process, or rebuild the FMU with this Python",
             record->version, whose, p_Py_GetVersion(), record->version);
    return -1;
}

int start_python(const struct runtime_record *record, char *error, size_t size)
{
    int result = 0;
    pthread_mutex_lock(&start_lock);
    if (python_ready) {
        result = check_version(record, "already running in this process", error, size);
    } else {
        __typeof__(&Py_IsInitialized) running =
            (__typeof__(&Py_IsInitialized))dlsym(RTLD_DEFAULT, "Py_IsInitialized");
        if (running && running()) {
            result = resolve(RTLD_DEFAULT, error, size) ||
                     check_version(record, "of this process", error, size);
        } else {
            void *library = record->library[0]
                ? dlopen(record->library, RTLD_NOW | RTLD_GLOBAL) : NULL;
            if (!library) {
                snprintf(error, size, "cannot load the Python library '%s' (%s); " FIX_HINT,
                         record->library,
                         record->library[0] ? dlerror() : "none was recorded");
                result = -1;
            } else {
                result = resolve(library, error, size) ||
                         check_version(record, "library", error, size) ||
                         resolve_init(library, error, size) ||
                         start_interpreter(record, error, size);
            }
        }
        if (result == 0) {
            pthread_key_create(&thread_state_key, release_thread_state);
            python_ready = 1;
        }
    }
    if (result == 0) {
        enter_python_thread();
        result = check_numpy(record, error, size);
    }
    pthread_mutex_unlock(&start_lock);
    return result;
}
