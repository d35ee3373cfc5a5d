/* The one-call step (issue 21), for FMI 2.0 and 3.0: the runtime keeps an
 * instance's inputs, parameters and outputs in C arrays, serves Real value
 * reads and input writes from them, and enters Python once per doStep (the
 * slave's fast_step; values cross as tuples of floats, converted here).  The
 * protocol, which this file follows, is the docstring of fmi/fast_step.py.  An instance whose
 * slave has no fast_step keeps plain calls (in->fast stays NULL): the
 * benchmarks' plain floor FMU does.  The GIL is taken per call, as pythonfmu
 * does, on the host thread's own thread state. */
#include "fast_path.h"
#include "python_api.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* The slave's layout: the runtime's own slave object, if it has the one-call step. */
static const char CLAIM[] =
    "sizes = ()\n"
    "methods = ('fast_step', 'fast_outputs', 'fast_load', 'fast_store', 'fast_layout')\n"
    "if all(hasattr(slave, m) for m in methods):\n"
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

/* One call into the slave with the GIL held; its status (an FMI status number). */
static long call(struct instance *in, enum fast_method method, PyObject *a, PyObject *b,
                 PyObject *c)
{
    struct fast_path *fast = in->fast;
    PyObject *const arguments[] = {a, b, c};
    size_t count = !a ? 0 : !b ? 1 : !c ? 2 : 3;
    PyObject *reply = p_PyObject_Vectorcall
                          ? p_PyObject_Vectorcall(fast->methods[method], arguments, count, NULL)
                          : p_PyObject_CallFunctionObjArgs(fast->methods[method], a, b, c, NULL);
    long status = reply ? take_reply(fast, method, reply) : -1;
    if (reply)
        p_Py_DecRef(reply);
    int raised = p_PyErr_Occurred() != NULL;
    p_PyErr_Clear();
    if (!fast->queue || p_PyList_Size(fast->queue) != 0)
        slave_drain(in, fast->slave);
    if (raised || status < 0 || status > fmi2Fatal) {
        reportf(in, fmi2Error, "the slave's %s failed", METHODS[method]);
        return fmi2Error;
    }
    return status;
}

static void forget(struct fast_path *fast)
{
    PyObject **owned[] = {&fast->slave,      &fast->methods[0], &fast->methods[1],
                          &fast->methods[2], &fast->methods[3], &fast->queue,
                          &fast->last_inputs, &fast->last_step};
    for (size_t i = 0; i < sizeof owned / sizeof *owned; i++) {
        if (*owned[i])
            p_Py_DecRef(*owned[i]);
        *owned[i] = NULL;
    }
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
    if (globals && in->object && !p_PyDict_SetItemString(globals, "slave", in->object))
        result = run_with(CLAIM, globals);
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

/* With the GIL: the claimed slave's methods, the arrays, and the known array
 * filled (fast_store); 0 if any of it fails. */
static int set_up(struct instance *in, struct fast_path *fast)
{
    if (!claim(in, fast))
        return 0;
    python_layout();
    double *known = realloc(fast->known, fast->known_size * sizeof *known);
    if (known)
        fast->known = known;
    double *values = known ? realloc(fast->values, fast->outputs * sizeof *values) : NULL;
    if (values)
        fast->values = values;
    /* A reply converts here first: a malformed one writes nothing. */
    double *scratch =
        values ? realloc(fast->scratch, (fast->outputs + fast->known_size) * sizeof *scratch)
               : NULL;
    if (!scratch)
        return 0;
    fast->scratch = scratch;
    for (int m = 0; m < 4; m++)
        fast->methods[m] = p_PyObject_GetAttrString(fast->slave, METHODS[m]);
    /* pythonfmu's slaves make the list once, in __init__, and only append to
     * it; one that is no list is drained by name at every call. */
    fast->queue = p_PyObject_GetAttrString(fast->slave, "log_queue");
    if (fast->queue && p_PyList_Size(fast->queue) < 0) {
        p_Py_DecRef(fast->queue);
        fast->queue = NULL;
    }
    int ok = 1;
    for (int m = 0; m < 4; m++)
        ok = ok && fast->methods[m];
    p_PyErr_Clear();
    fast->stale = 1, fast->inputs_written = 0;
    return ok && call(in, FAST_STORE, NULL, NULL, NULL) == fmi2OK;
}

static void drop(struct instance *in)
{
    struct fast_path *fast = in->fast;
    forget(fast);
    free(fast->known);
    free(fast->values);
    free(fast->scratch);
    free(fast->table);
    free(fast);
    in->fast = NULL;
}

void fast_attach(struct instance *in)
{
    if (!python_api() || !(in->fast = calloc(1, sizeof *in->fast)))
        return;
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

/* One call into the slave, the GIL taken for it: fast_step(time, step, inputs),
 * fast_outputs(inputs), fast_load(inputs) or fast_store(). */
long fast_call(struct instance *in, enum fast_method method, double time, double step)
{
    struct fast_path *fast = in->fast;
    PyGILState_STATE gil = p_PyGILState_Ensure();
    PyObject *inputs = method == FAST_STORE ? NULL : inputs_tuple(fast);
    PyObject *t = NULL, *h = NULL;
    if (method == FAST_STEP) {
        t = p_PyFloat_FromDouble(time);
        h = float_like(fast->last_step, step);
        if (h)
            keep(&fast->last_step, h);
    }
    long status;
    if (method == FAST_STORE)
        status = call(in, method, NULL, NULL, NULL);
    else if (!inputs || (method == FAST_STEP && !(t && h))) {
        reportf(in, fmi2Error, "the slave's %s failed: no memory for its arguments",
                METHODS[method]);
        status = fmi2Error;
    } else if (method == FAST_STEP)
        status = call(in, method, t, h, inputs);
    else
        status = call(in, method, inputs, NULL, NULL);
    PyObject *owned[] = {inputs, t, h};
    for (size_t i = 0; i < 3; i++)
        if (owned[i])
            p_Py_DecRef(owned[i]);
    p_PyErr_Clear();
    p_PyGILState_Release(gil);
    return status;
}
