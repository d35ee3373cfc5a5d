/* The one place the runtime's Python C API is resolved (python_api.h). */
#define _GNU_SOURCE
#include "python_api.h"

#include <dlfcn.h>
#include <pthread.h>

#define DEFINE(result, name, parameters) result(*p_##name) parameters;
PYTHON_FUNCTIONS(DEFINE)
#undef DEFINE
PyObject *py_none;
PyObject *const *py_keyboard_interrupt;

static int resolved;
static pthread_once_t once = PTHREAD_ONCE_INIT;

static void resolve(void)
{
#define RESOLVE(result, name, parameters)                                                 \
    if (!(*(void **)&p_##name = dlsym(RTLD_DEFAULT, #name)))                              \
        return;
    PYTHON_FUNCTIONS(RESOLVE)
#undef RESOLVE
    py_none = dlsym(RTLD_DEFAULT, "_Py_NoneStruct");
    py_keyboard_interrupt = dlsym(RTLD_DEFAULT, "PyExc_KeyboardInterrupt");
    resolved = py_none != NULL && py_keyboard_interrupt != NULL;
}

int python_api(void)
{
    pthread_once(&once, resolve);
    return resolved;
}

int set_global(PyObject *globals, const char *name, PyObject *value)
{
    int ok = value && !p_PyDict_SetItemString(globals, name, value);
    if (value)
        p_Py_DecRef(value);
    return ok;
}

PyObject *run_with(const char *code, PyObject *globals)
{
    if (p_PyDict_SetItemString(globals, "__builtins__", p_PyEval_GetBuiltins()))
        return NULL;
    return p_PyRun_String(code, PY_FILE_INPUT, globals, globals);
}
