/* The fast path, for FMI 2.0 and 3.0: the runtime keeps an instance's inputs,
 * parameters and outputs in C arrays, serves Real value reads and input writes
 * from them, runs the generated step on them (generated.c), and keeps the
 * slave in step with them around every call into it (values cross as tuples
 * of floats, converted here).  The protocol, which this file follows, is the
 * docstring of fmi/fast_path.py.  An instance whose slave has no fast_*
 * methods or value reference table keeps plain calls (in->fast stays NULL):
 * the benchmarks' plain floor FMU does.  The GIL is taken per call, as
 * pythonfmu does, on the host thread's own thread state. */
#include "fast_path.h"
#include "python_api.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* The slave's layout: the runtime's own slave object, if it has the fast path's methods. */
static const char CLAIM[] =
    "sizes = ()\n"
    "methods = ('fast_outputs', 'fast_load', 'fast_store', 'fast_do_step', 'fast_layout')\n"
    "if all(hasattr(slave, m) for m in methods):\n"
    "    layout = slave.fast_layout()\n"
    "    sizes = tuple(int(layout[k]) for k in ('inputs', 'known_size', 'first_output', "
    "'outputs'))\n"
    "found = int(len(sizes) == 4 and 0 < sizes[0] <= sizes[1] == sizes[2] and sizes[3] > 0)\n"
    "if found:\n"
    "    inputs, known_size, first_output, outputs = sizes\n"
    "    # The step state, handed over only to a runtime with the model's step in C.\n"
    "    state_size = int(slave.fast_state_size()) if generated and all(hasattr(slave, m) "
    "for m in ('fast_state_size', 'fast_sync', 'fast_watch')) else 0\n"
    "    # Value reference -> flat indices (the slave's _FLAT), as int64s: the\n"
    "    # count of references, each one's first index, the end, then the indices.\n"
    "    refs = getattr(slave, 'fast_flat', None)\n"
    "    starts = [0]\n"
    "    for ref in refs or ():\n"
    "        starts.append(starts[-1] + len(ref))\n"
    "    import array\n"
    "    flat_table = array.array('q', [len(refs), *starts, *(i for r in refs for i in r)]"
    ").tobytes() if refs else b''\n";

/* In the order of enum fast_method. */
static const char *const METHODS[] = {"fast_outputs", "fast_load", "fast_store",
                                      "fast_do_step", "fast_sync",  "fast_watch"};

/* One call into the slave with the GIL held; its status (an FMI status number). */
static long call(struct instance *in, enum fast_method method, PyObject *a, PyObject *b,
                 PyObject *c, PyObject *d)
{
    struct fast_path *fast = in->fast;
    /* the arguments end at the first NULL */
    PyObject *reply = p_PyObject_CallFunctionObjArgs(fast->methods[method], a, b, c, d, NULL);
    /* A step that raised (do_step's own fault, or the host's interrupt) is
     * said as slave_do_step says it. */
    if (!reply && method == FAST_STEP)
        return fast->answer = slave_finish(in, NULL, "do_step");
    long status = reply ? take_reply(fast, method, reply) : -1;
    if (reply)
        p_Py_DecRef(reply);
    int interrupted = !reply && slave_interrupted(in, METHODS[method]);
    int raised = p_PyErr_Occurred() != NULL;
    p_PyErr_Clear();
    if (!fast->queue || p_PyList_Size(fast->queue) != 0)
        slave_drain(in, fast->slave);
    slave_hand_back(interrupted);
    if (interrupted)
        return fmi2Error;
    if (raised || status < 0 || status > fmi2Fatal) {
        reportf(in, fmi2Error, "the slave's %s failed", METHODS[method]);
        return fmi2Error;
    }
    return status;
}

static void forget(struct fast_path *fast)
{
    PyObject **owned[FAST_METHODS + 2] = {&fast->slave, &fast->queue};
    for (int m = 0; m < FAST_METHODS; m++)
        owned[m + 2] = &fast->methods[m];
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

/* The value references' flat indices (CLAIM's flat_table): 0 without one. */
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
    PyObject *generated = p_PyLong_FromLong(generated_compiled());
    if (globals && generated && in->object &&
        !p_PyDict_SetItemString(globals, "slave", in->object) &&
        !p_PyDict_SetItemString(globals, "generated", generated))
        result = run_with(CLAIM, globals);
    if (generated)
        p_Py_DecRef(generated);
    int found = result && global_long(globals, "found") == 1;
    if (found) {
        fast->slave = p_PyDict_GetItemString(globals, "slave");
        p_Py_IncRef(fast->slave);
        fast->inputs = global_long(globals, "inputs");
        fast->known_size = global_long(globals, "known_size");
        fast->first_output = global_long(globals, "first_output");
        fast->outputs = global_long(globals, "outputs");
        fast->state_size = global_long(globals, "state_size");
        found = sizes_taken(in, fast) &&
                read_flat_table(fast, p_PyDict_GetItemString(globals, "flat_table"));
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
    double *flat = realloc(fast->flat, (fast->known_size + fast->outputs) * sizeof *flat);
    if (flat)
        fast->flat = fast->known = flat, fast->values = flat + fast->first_output;
    /* A reply converts here first: a malformed one writes nothing.  The largest
     * is fast_store's: known values, outputs, state, limits. */
    long reply_size = fast->known_size + fast->outputs + fast->state_size + fast->outputs;
    double *scratch = flat ? realloc(fast->scratch, reply_size * sizeof *scratch) : NULL;
    if (scratch)
        fast->scratch = scratch;
    double *state = scratch ? realloc(fast->state, (fast->state_size + 1) * sizeof *state) : NULL;
    if (state)
        fast->state = state;
    double *limits = state ? realloc(fast->limits, fast->outputs * sizeof *limits) : NULL;
    if (!limits)
        return 0;
    fast->limits = limits;
    for (long k = 0; k < fast->outputs; k++) /* none armed until fast_store says */
        limits[k] = INFINITY;
    fast->generated = fast->state_size > 0 && generated_attach(fast);
    int methods = fast->state_size > 0 ? FAST_METHODS : FAST_SYNC;
    for (int m = 0; m < methods; m++)
        fast->methods[m] = p_PyObject_GetAttrString(fast->slave, METHODS[m]);
    /* pythonfmu's slaves make the list once, in __init__, and only append to
     * it; one that is no list is drained by name at every call. */
    fast->queue = p_PyObject_GetAttrString(fast->slave, "log_queue");
    if (fast->queue && p_PyList_Size(fast->queue) < 0) {
        p_Py_DecRef(fast->queue);
        fast->queue = NULL;
    }
    int ok = 1;
    for (int m = 0; m < methods; m++)
        ok = ok && fast->methods[m];
    p_PyErr_Clear();
    fast->stale = 1, fast->inputs_written = 0, fast->behind = 0;
    return ok && call(in, FAST_STORE, NULL, NULL, NULL, NULL) == fmi2OK;
}

static void drop(struct instance *in)
{
    struct fast_path *fast = in->fast;
    forget(fast);
    free(fast->flat);
    free(fast->scratch);
    free(fast->table);
    free(fast->serves);
    free(fast->single);
    free(fast->state);
    free(fast->limits);
    free(fast->arguments);
    free(fast->results);
    free(fast->held);
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

/* Before any call into the slave once steps were taken in C: the slave takes
 * the state, clock, inputs and outputs they left (fast_sync).  A slave that
 * cannot (a fault, reported) is behind the instance for good: any call it
 * answered would act on a state the host has left, so the instance enters
 * the error state, where only reset (a new slave) and free are allowed. */
int catch_up(struct instance *in)
{
    struct fast_path *fast = in->fast;
    if (!fast->behind)
        return 0;
    fast->behind = 0;
    if (fast_call(in, FAST_SYNC) == fmi2OK)
        return 0;
    fast->generated = 0;
    in->state = STATE_ERROR;
    reportf(in, fmi2Error, "the slave could not take the state of the steps taken in C (to "
            "t = %.17g s); it is behind the instance, which can only be reset or freed now",
            fast->behind_time);
    return -1;
}

/* One call into the slave, the GIL taken for it: fast_outputs(inputs, read),
 * fast_load(inputs), fast_store(), fast_do_step(step_time, step_size[,
 * inputs when written]), fast_sync(behind_time, state, held inputs, outputs)
 * or fast_watch(). */
long fast_call(struct instance *in, enum fast_method method)
{
    struct fast_path *fast = in->fast;
    if (method != FAST_SYNC && catch_up(in))
        return fmi2Error;
    PyGILState_STATE gil = p_PyGILState_Ensure();
    PyObject *arguments[4] = {NULL, NULL, NULL, NULL};
    int made = 1;
    if (method == FAST_SYNC) {
        arguments[0] = p_PyFloat_FromDouble(fast->behind_time);
        arguments[1] = tuple_of(fast->state, fast->state_size);
        arguments[2] = tuple_of(fast->held, fast->inputs);
        arguments[3] = tuple_of(fast->values, fast->outputs);
        made = arguments[0] && arguments[1] && arguments[2] && arguments[3];
    } else if (method == FAST_STEP) {
        arguments[0] = p_PyFloat_FromDouble(fast->step_time);
        arguments[1] = p_PyFloat_FromDouble(fast->step_size);
        if (fast->inputs_written)
            arguments[2] = tuple_of(fast->known, fast->inputs);
        made = arguments[0] && arguments[1] && (!fast->inputs_written || arguments[2]);
    } else if (method != FAST_STORE && method != FAST_WATCH) {
        arguments[0] = tuple_of(fast->known, fast->inputs);
        /* fast_outputs(inputs, read): only a read of a held output warns. */
        if (method == FAST_OUTPUTS && arguments[0])
            arguments[1] = read_indices(fast);
        made = arguments[0] != NULL && (method != FAST_OUTPUTS || arguments[1] != NULL);
    }
    long status;
    if (made)
        status = call(in, method, arguments[0], arguments[1], arguments[2], arguments[3]);
    else {
        reportf(in, fmi2Error, "the slave's %s failed: no memory for its arguments",
                METHODS[method]);
        status = fmi2Error;
    }
    for (size_t i = 0; i < 4; i++)
        if (arguments[i])
            p_Py_DecRef(arguments[i]);
    p_PyErr_Clear();
    p_PyGILState_Release(gil);
    return status;
}
