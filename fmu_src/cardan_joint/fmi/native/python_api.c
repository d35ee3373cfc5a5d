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
PyObject *(*p_PyObject_Vectorcall)(PyObject *, PyObject *const *, size_t, PyObject *);
const void *py_float_type, *py_tuple_type;

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
    *(void **)&p_PyObject_Vectorcall = dlsym(RTLD_DEFAULT, "PyObject_Vectorcall");
    resolved = py_none != NULL && py_keyboard_interrupt != NULL;
}

void python_layout(void)
{
    static int checked; /* the GIL orders the callers */
    if (checked)
        return;
    checked = 1;
    const void *float_type = dlsym(RTLD_DEFAULT, "PyFloat_Type");
    const void *tuple_type = dlsym(RTLD_DEFAULT, "PyTuple_Type");
    PyObject *x = float_type && tuple_type ? p_PyFloat_FromDouble(0.3125) : NULL;
    PyObject *t = x ? p_PyTuple_New(1) : NULL;
    int holds = 0;
    if (t) {
        p_Py_IncRef(x); /* the tuple takes a reference */
        const struct py_float_layout *fl = (const void *)x;
        const struct py_tuple_layout *tl = (const void *)t;
        /* The type first: only a matching one says the fields after it are there. */
        holds = !p_PyTuple_SetItem(t, 0, x) && fl->head.type == float_type &&
                tl->head.type == tuple_type && fl->value == 0.3125 && tl->size == 1 &&
                tl->items[0] == x;
        p_Py_DecRef(t);
    }
    if (x)
        p_Py_DecRef(x);
    /* Published only once found: until then every reader calls the API. */
    if (holds)
        py_float_type = float_type, py_tuple_type = tuple_type;
    p_PyErr_Clear();
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
