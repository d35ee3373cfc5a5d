/* The one-call step (issue 21), for FMI 2.0 and 3.0: the loader keeps an
 * instance's inputs, parameters and outputs in C arrays, serves Real value
 * reads and input writes from them, and enters Python once per doStep (the
 * slave's fast_step on memoryviews over the arrays).  The protocol, which this
 * file follows, is the docstring of fmi/fast_step.py.  An instance whose
 * slave has no fast_step (or, FMI 3.0, cannot be claimed) keeps plain calls
 * (in->fast stays NULL): the benchmarks' plain floor FMU does.
 *
 * Python is reached as in slave_module.c: no headers, functions looked up in
 * the process's global scope, one ABI for CPython 3.10-3.13; the GIL is taken
 * per call, as pythonfmu does, on the host thread's own thread state. */
#define _GNU_SOURCE
#include "fast_path.h"

#include <dlfcn.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <sys/types.h>

typedef ssize_t Py_ssize_t;
typedef int PyGILState_STATE; /* an enum in Python.h */
#define PY_FILE_INPUT 257
#define PYBUF_WRITE 0x200

#define FAST_FUNCTIONS(X)                                                                 \
    X(PyGILState_STATE, PyGILState_Ensure, (void))                                        \
    X(void, PyGILState_Release, (PyGILState_STATE))                                       \
    X(PyObject *, PyMemoryView_FromMemory, (char *, Py_ssize_t, int))                     \
    X(PyObject *, PyObject_GetAttrString, (PyObject *, const char *))                     \
    X(PyObject *, PyObject_CallFunctionObjArgs, (PyObject *, ...))                        \
    X(PyObject *, PyFloat_FromDouble, (double)) X(long, PyLong_AsLong, (PyObject *))      \
    X(PyObject *, PyDict_New, (void)) X(PyObject *, PyEval_GetBuiltins, (void))           \
    X(int, PyDict_SetItemString, (PyObject *, const char *, PyObject *))                  \
    X(PyObject *, PyDict_GetItemString, (PyObject *, const char *))                       \
    X(PyObject *, PyUnicode_FromString, (const char *))                                   \
    X(PyObject *, PyUnicode_DecodeFSDefault, (const char *))                              \
    X(PyObject *, PyRun_String, (const char *, int, PyObject *, PyObject *))              \
    X(const char *, PyUnicode_AsUTF8, (PyObject *))                                       \
    X(Py_ssize_t, PyList_Size, (PyObject *))                                              \
    X(PyObject *, PyList_GetItem, (PyObject *, Py_ssize_t))                               \
    X(int, PyList_SetSlice, (PyObject *, Py_ssize_t, Py_ssize_t, PyObject *))             \
    X(void, Py_IncRef, (PyObject *)) X(void, Py_DecRef, (PyObject *))                     \
    X(PyObject *, PyErr_Occurred, (void)) X(void, PyErr_Clear, (void))                    \
    X(int, PyBytes_AsStringAndSize, (PyObject *, char **, Py_ssize_t *))

#define DECLARE(result, name, parameters) static result(*p_##name) parameters;
FAST_FUNCTIONS(DECLARE)
#undef DECLARE
static PyObject *none;

/* The slave's layout: FMI 2.0 passes the runtime's own slave object; FMI 3.0
 * (slave None) claims the one pythonfmu3 just constructed on this thread
 * (fmi/fast_step.py fast_claim), through the script module. */
static const char CLAIM[] =
    "import sys\n"
    "with open(resources + '/slavemodule.txt') as file:\n"
    "    script = sys.modules.get(file.readline().strip())\n"
    "sizes = ()\n"
    "for value in list(vars(script).values()) if script and slave is None else ():\n"
    "    if isinstance(value, type) and hasattr(value, 'fast_claim'):\n"
    "        slave = value.fast_claim(name)\n"
    "        break\n"
    "methods = ('fast_step', 'fast_outputs', 'fast_load', 'fast_store', 'fast_layout')\n"
    "if slave is not None and all(hasattr(slave, m) for m in methods):\n"
    "    layout = slave.fast_layout()\n"
    "    sizes = tuple(int(layout[k]) for k in ('inputs', 'known_size', 'first_output', "
    "'outputs'))\n"
    "found = int(len(sizes) == 4 and 0 < sizes[0] <= sizes[1] == sizes[2] and sizes[3] > 0)\n"
    "if found:\n"
    "    inputs, known_size, first_output, outputs = sizes\n"
    "    # FMI 3: value reference -> flat indices (slave3._FLAT), as int64s: the\n"
    "    # count of references, each one's first index, the end, then the indices.\n"
    "    refs = getattr(slave, 'fast_flat', None)\n"
    "    starts = [0]\n"
    "    for ref in refs or ():\n"
    "        starts.append(starts[-1] + len(ref))\n"
    "    import array\n"
    "    flat_table = array.array('q', [len(refs), *starts, *(i for r in refs for i in r)]"
    ").tobytes() if refs else b''\n";

/* In the order of enum fast_method. */
static const char *const METHODS[] = {"fast_step", "fast_outputs", "fast_load", "fast_store"};

static int resolve(void)
{
    static int resolved = -1;
    if (resolved >= 0)
        return resolved;
#define RESOLVE(result, name, parameters)                                                 \
    if (!(*(void **)&p_##name = dlsym(RTLD_DEFAULT, #name)))                              \
        return resolved = 0;
    FAST_FUNCTIONS(RESOLVE)
#undef RESOLVE
    none = dlsym(RTLD_DEFAULT, "_Py_NoneStruct");
    return resolved = none != NULL;
}

/* One call into the slave with the GIL held; its status (an FMI status number). */
static long call(struct instance *in, enum fast_method method, PyObject *a, PyObject *b,
                 PyObject *c, PyObject *d)
{
    struct fast_path *fast = in->fast;
    PyObject *result = p_PyObject_CallFunctionObjArgs(fast->methods[method], a, b, c, d, NULL);
    long status = result ? p_PyLong_AsLong(result) : -1;
    if (result)
        p_Py_DecRef(result);
    int raised = p_PyErr_Occurred() != NULL;
    p_PyErr_Clear();
    slave_drain(in, fast->slave);
    if (raised || status < 0 || status > fmi2Fatal) {
        reportf(in, fmi2Error, "the slave's %s failed", METHODS[method]);
        return fmi2Error;
    }
    return status;
}

static void forget(struct fast_path *fast)
{
    PyObject **owned[] = {&fast->slave, &fast->views[0], &fast->views[1], &fast->methods[0],
                          &fast->methods[1], &fast->methods[2], &fast->methods[3]};
    for (size_t i = 0; i < sizeof owned / sizeof *owned; i++) {
        if (*owned[i])
            p_Py_DecRef(*owned[i]);
        *owned[i] = NULL;
    }
}

static int set_global(PyObject *globals, const char *name, PyObject *value)
{
    int ok = value && !p_PyDict_SetItemString(globals, name, value);
    if (value)
        p_Py_DecRef(value);
    return ok;
}

static long global_long(PyObject *globals, const char *name)
{
    PyObject *value = p_PyDict_GetItemString(globals, name);
    return value ? p_PyLong_AsLong(value) : 0;
}

/* FMI 3's value references (CLAIM's flat_table), or none for FMI 2's flat ones. */
static int read_flat_table(struct fast_path *fast, PyObject *table)
{
    char *bytes;
    Py_ssize_t size;
    return table && !p_PyBytes_AsStringAndSize(table, &bytes, &size) &&
           fast_table(fast, bytes, (size_t)size);
}

/* With the GIL: the instance's slave and its layout; 0 if none fits. */
static int claim(struct instance *in, struct fast_path *fast)
{
    PyObject *globals = p_PyDict_New(), *result = NULL;
    if (globals &&
        set_global(globals, "resources", p_PyUnicode_DecodeFSDefault(fast->resources)) &&
        set_global(globals, "name", p_PyUnicode_FromString(in->name)) &&
        !p_PyDict_SetItemString(globals, "slave", in->object ? in->object : none) &&
        !p_PyDict_SetItemString(globals, "__builtins__", p_PyEval_GetBuiltins()))
        result = p_PyRun_String(CLAIM, PY_FILE_INPUT, globals, globals);
    int found = result && global_long(globals, "found") == 1;
    if (found) {
        fast->slave = p_PyDict_GetItemString(globals, "slave");
        p_Py_IncRef(fast->slave);
        fast->inputs = global_long(globals, "inputs");
        fast->known_size = global_long(globals, "known_size");
        fast->first_output = global_long(globals, "first_output");
        fast->outputs = global_long(globals, "outputs");
        found = read_flat_table(fast, p_PyDict_GetItemString(globals, "flat_table"));
    }
    if (result)
        p_Py_DecRef(result);
    if (globals)
        p_Py_DecRef(globals);
    p_PyErr_Clear();
    return found;
}

/* With the GIL: the claimed slave's methods, the arrays and their views, and
 * the arrays filled (fast_store); 0 if any of it fails. */
static int set_up(struct instance *in, struct fast_path *fast)
{
    if (!claim(in, fast))
        return 0;
    double *known = realloc(fast->known, fast->known_size * sizeof *known);
    if (known)
        fast->known = known;
    double *values = known ? realloc(fast->values, fast->outputs * sizeof *values) : NULL;
    if (!values)
        return 0;
    fast->values = values;
    fast->views[0] = p_PyMemoryView_FromMemory((char *)fast->known,
                                               fast->known_size * (Py_ssize_t)sizeof(double),
                                               PYBUF_WRITE);
    fast->views[1] = p_PyMemoryView_FromMemory((char *)fast->values,
                                               fast->outputs * (Py_ssize_t)sizeof(double),
                                               PYBUF_WRITE);
    for (int m = 0; m < 4; m++)
        fast->methods[m] = p_PyObject_GetAttrString(fast->slave, METHODS[m]);
    int ok = fast->views[0] && fast->views[1];
    for (int m = 0; m < 4; m++)
        ok = ok && fast->methods[m];
    p_PyErr_Clear();
    fast->stale = 1, fast->inputs_written = 0;
    return ok && call(in, FAST_STORE, fast->views[0], NULL, NULL, NULL) == fmi2OK;
}

static void drop(struct instance *in)
{
    struct fast_path *fast = in->fast;
    forget(fast);
    free(fast->known);
    free(fast->values);
    free(fast->table);
    free(fast->resources);
    free(fast);
    in->fast = NULL;
}

void fast_attach(struct instance *in, const char *resources)
{
    if (!resolve() || !(in->fast = calloc(1, sizeof *in->fast)))
        return;
    in->fast->resources = copy_of(resources);
    PyGILState_STATE gil = p_PyGILState_Ensure();
    if (!set_up(in, in->fast))
        drop(in);
    p_PyGILState_Release(gil);
}

/* Before the instance is freed, or after a reset (again: its new slave, else
 * plain calls from now on). */
static void renew(struct instance *in, int again)
{
    if (!in->fast)
        return;
    PyGILState_STATE gil = p_PyGILState_Ensure();
    forget(in->fast);
    if (!again || !set_up(in, in->fast))
        drop(in);
    p_PyGILState_Release(gil);
}

void fast_detach(struct instance *in) { renew(in, 0); }
void fast_reset(struct instance *in) { renew(in, 1); }

/* One call into the slave, the GIL taken for it: fast_step(time, step, known,
 * outputs), fast_outputs(known, outputs), fast_load(known) or fast_store(known). */
long fast_call(struct instance *in, enum fast_method method, double time, double step)
{
    struct fast_path *fast = in->fast;
    PyGILState_STATE gil = p_PyGILState_Ensure();
    long status;
    if (method == FAST_STEP) {
        PyObject *t = p_PyFloat_FromDouble(time), *h = p_PyFloat_FromDouble(step);
        status = t && h ? call(in, method, t, h, fast->views[0], fast->views[1]) : fmi2Error;
        if (t)
            p_Py_DecRef(t);
        if (h)
            p_Py_DecRef(h);
    } else {
        status = call(in, method, fast->views[0], method == FAST_OUTPUTS ? fast->views[1] : NULL,
                      NULL, NULL);
    }
    p_PyGILState_Release(gil);
    return status;
}
