/* Starting (or joining) and entering the Python that runs the FMU's slave.
 *
 * A Python host (FMPy, libcosimpy, a statically linked python3) already has
 * one: use it, whatever its 3.x from the record's minimum, never a second
 * interpreter.  A C host has none: load the one find_python names RTLD_GLOBAL
 * (extension modules resolve their symbols in the global scope) and start it
 * isolated from the environment with that home and search path
 * (python_start.c).
 *
 * Every copy of this runtime in a process (several FMUs, FMI 2.0 and 3.0)
 * agrees on one start through one process-wide object (process_object.c),
 * under its lock.
 *
 * No Python headers: every function is looked up with dlsym and declared here,
 * so that one binary starts every CPython of config_layout.h's table and any
 * machine with a C compiler builds it.
 */
#define _GNU_SOURCE
#include "loader.h"
#include "process_object.h"

#include <dlfcn.h>
#include <limits.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/syscall.h>
#include <unistd.h>

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

#define DECLARE(result, name, parameters) static result(*p_##name) parameters;
PY_FUNCTIONS(DECLARE)

static struct process_python *process; /* the process's, once its layout is this copy's */
static int python_ready;   /* this copy has resolved its functions; under process->lock */
static pthread_key_t thread_state_key;

const char *python_in_use(void)
{
    const struct process_python *shared = __atomic_load_n(&process, __ATOMIC_ACQUIRE);
    return shared && shared->in_use[0] ? shared->in_use : "no Python";
}

static void describe(const char *where)
{
    const char *version = p_Py_GetVersion();
    snprintf(process->in_use, sizeof process->in_use, "Python %.*s %s",
             (int)strcspn(version, " "), version, where);
}

#define RESOLVE(result, name, parameters)                                                \
    if (!(*(void **)&p_##name = dlsym(library, #name))) {                                \
        snprintf(error, size, "%s has no %s: not a CPython 3", where, #name);            \
        return -1;                                                                       \
    }

static int resolve(void *library, const char *where, char *error, size_t size)
{
    PY_FUNCTIONS(RESOLVE)
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
    snprintf(error, size, "this FMU needs CPython 3.%d or newer, but the Python %s is %.*s "
             "(the minimum is its resources/" RUNTIME_RECORD "'s); run it in a Python 3.%d "
             "or newer process", record->minimum_minor, whose, (int)strcspn(version, " "),
             version, record->minimum_minor);
    return -1;
}

/* `loaded`: the libpython the process holds already (not running), else NULL. */
static int load_and_start(const struct runtime_record *record, const char *loaded,
                          char *error, size_t size)
{
    struct python_location python;
    if (loaded ? locate_loaded(record, loaded, &python, error, size)
               : find_python(record, &python, error, size))
        return -1;
    void *library = dlopen(python.library, RTLD_NOW | RTLD_GLOBAL);
    if (!library) {
        snprintf(error, size, "cannot load the Python library '%s' (%s); " FIX_HINT,
                 python.library, dlerror());
        return -1;
    }
    int minor = -1, started = -1;
    if (resolve(library, python.library, error, size) ||
        check_version(record, python.library, error, size) ||
        sscanf(p_Py_GetVersion(), "3.%d", &minor) != 1 ||
        (started = start_interpreter(library, minor, &python, error, size)) != 0) {
        if (started == -2)
            return -2;  /* tried: the library stays, its runtime half-started */
        dlclose(library);
        return -1;
    }
    p_PyEval_SaveThread();  /* the GIL is free; this thread keeps its main thread state */
    char where[sizeof python.library + 8];
    snprintf(where, sizeof where, "from %s", python.library);
    describe(where);
    return 0;
}

/* A Python the process holds that is not running in the global scope: one
 * libpython loaded in any scope is joined if it runs (a plugin's RTLD_LOCAL
 * Python, made global for the slave's calls and its extension modules), else
 * started (loaded and never started, or finalized by the host); several are
 * refused by name; none: the one discovery finds.  Never a second libpython. */
static int join_or_start(const struct runtime_record *record, char *error, size_t size)
{
    char loaded[PATH_MAX], names[1024];
    int n = loaded_pythons(loaded, sizeof loaded, names, sizeof names);
    if (n > 1) {
        snprintf(error, size, "this process already holds %d Python libraries (%s), none "
                 "running: the FMU's runtime loads no other beside them and cannot tell which "
                 "to start; run it in a process with one", n, names);
        return -1;
    }
    void *library = n ? dlopen(loaded, RTLD_NOW | RTLD_NOLOAD | RTLD_GLOBAL) : NULL;
    int (*running)(void) = library ? (int (*)(void))dlsym(library, "Py_IsInitialized") : NULL;
    if (!running || !running())
        return load_and_start(record, n ? loaded : NULL, error, size);
    if (resolve(library, loaded, error, size) ||
        check_version(record, "of this process", error, size))
        return -1;
    char where[PATH_MAX + 32];
    snprintf(where, sizeof where, "(the host's, from %s)", loaded);
    describe(where);
    return 0;
}

/* A host thread without a Python thread state keeps the one it gets here until
 * it exits: pythonfmu's PyGILState_Ensure/Release on every call would otherwise
 * create and destroy one each time, which costs more than the step itself.
 *
 * At thread exit the state is ended by hand (PyGILState_Release would not find
 * it), and while CPython's own thread-specific slot still names it: a debug
 * build's allocator checks the GIL through that slot (PyGILState_Check), and
 * glibc empties every slot of a key older than ours, CPython's included, before
 * it calls our key's destructor.  glibc >= 2.18 runs the destructors registered
 * with __cxa_thread_atexit_impl (C++'s thread_local) before it touches any slot:
 * those end the state.  Looked up, not linked (glibc 2.17 has none: there the
 * key's destructor does it, which a release build does not check).  Not for the
 * process's main thread: exit() runs them too, while other threads may hold the
 * GIL. */
static void release_thread_state(void *thread_state)
{
    if (p_Py_IsInitialized && p_Py_IsInitialized()) {
        p_PyEval_RestoreThread(thread_state);
        p_PyThreadState_Clear(thread_state);
        p_PyThreadState_DeleteCurrent();
    }
}

typedef int (*thread_atexit)(void (*)(void *), void *, void *);
static thread_atexit at_thread_exit; /* set with python_ready */
extern void *__dso_handle;           /* this library, for glibc's count of its users */

int enter_python_thread(void)
{
    static __thread int entered;
    /* Every call: a host may finalize the Python the slaves live in. */
    if (!p_Py_IsInitialized || !p_Py_IsInitialized())
        return -1;
    if (entered)
        return 0;
    entered = 1;
    if (p_PyGILState_GetThisThreadState())
        return 0;  /* a Python thread, or the one that started Python */
    p_PyGILState_Ensure();
    PyThreadState *state = p_PyEval_SaveThread();
    int main_thread = syscall(SYS_gettid) == getpid();
    if (main_thread || !at_thread_exit ||
        at_thread_exit(release_thread_state, state, &__dso_handle) != 0)
        pthread_setspecific(thread_state_key, state);
    return 0;
}

int start_python(const struct runtime_record *record, char *error, size_t size)
{
    int result = 0;
    struct process_python *shared = process_object(error, size);
    if (!shared)
        return -1;
    __atomic_store_n(&process, shared, __ATOMIC_RELEASE); /* the same from every thread */
    pthread_mutex_lock(&process->lock);
    if (python_ready && !p_Py_IsInitialized()) {
        snprintf(error, size, "%s is not running any more: the host finalized it, and the "
                 "slaves' modules cannot be started again in this process", python_in_use());
        result = -1;
    } else if (python_ready) {
        result = check_version(record, "already running in this process", error, size);
    } else if (process->state < 0) {
        /* A failed Py_InitializeFromConfig is not tried again: the runtime is half set up. */
        snprintf(error, size, "%s", process->failure);
        result = -1;
    } else {
        int (*running)(void) = (int (*)(void))dlsym(RTLD_DEFAULT, "Py_IsInitialized");
        if (running && running()) {  /* the host's, or one another copy started */
            result = resolve(RTLD_DEFAULT, "this process's Python", error, size) ||
                     check_version(record, "of this process", error, size);
            if (result == 0 && !process->in_use[0])
                describe("(the host's)");
        } else if (process->state == 1) {
            snprintf(error, size, "the Python another FMU started in this process is not "
                     "running any more");
            result = -1;
        } else {
            result = join_or_start(record, error, size);
            if (result == -2) {
                process->state = -1;
                snprintf(process->failure, sizeof process->failure, "%s", error);
            } else if (result == 0)
                process->state = 1;
        }
        if (result == 0) {
            pthread_key_create(&thread_state_key, release_thread_state);
            *(void **)&at_thread_exit = dlsym(RTLD_DEFAULT, "__cxa_thread_atexit_impl");
            python_ready = 1;
        }
    }
    if (result == 0)
        enter_python_thread();
    pthread_mutex_unlock(&process->lock);
    return result ? -1 : 0;
}
