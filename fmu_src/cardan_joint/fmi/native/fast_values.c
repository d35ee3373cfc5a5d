/* The fast path's values (the protocol: fmi/fast_path.py): the arguments
 * made and the replies read, input writes and Real reads answered from the
 * instance's arrays, doStep by the generated step or by the slave, and the
 * slave kept in step with the arrays around every call into it (fast_path.c
 * sets the arrays up and makes the calls). */
#include "fast_path.h"
#include "python_api.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

PyObject *tuple_of(const double *values, long n)
{
    PyObject *tuple = p_PyTuple_New(n);
    for (long i = 0; tuple && i < n; i++) {
        PyObject *item = p_PyFloat_FromDouble(values[i]);
        if (!item || p_PyTuple_SetItem(tuple, i, item)) {
            p_Py_DecRef(tuple);
            tuple = NULL;
        }
    }
    return tuple;
}

/* Where a method's values go, in order (the protocol: fmi/fast_path.py):
 * every known value or the outputs, then for fast_store the outputs, the step
 * state and the limits when the slave hands them over; how many parts. */
struct part {
    double *into;
    long count;
};

static int destinations(const struct fast_path *fast, enum fast_method method, struct part part[4])
{
    int n = 0;
    if (method == FAST_STORE)
        part[n++] = (struct part){fast->known, fast->known_size};
    if (method == FAST_STORE || method == FAST_OUTPUTS)
        part[n++] = (struct part){fast->values, fast->outputs};
    if (method == FAST_STORE && fast->state_size > 0)
        part[n++] = (struct part){fast->state, fast->state_size};
    if ((method == FAST_STORE && fast->state_size > 0) || method == FAST_WATCH)
        part[n++] = (struct part){fast->limits, fast->outputs};
    return n;
}

/* The status of a reply (a status, or (status, values, ...): tuples of
 * floats, in order), the values written into the arrays only when every one
 * of them converts and they are as many as the method gives; -1 otherwise. */
long take_reply(struct fast_path *fast, enum fast_method method, PyObject *reply)
{
    Py_ssize_t size = p_PyTuple_Size(reply);
    if (method == FAST_STEP) {
        /* (do_step's result, fast_store's reply); the store's status */
        if (size != 2) {
            p_PyErr_Clear();
            return -1;
        }
        fast->answer = step_answer(p_PyTuple_GetItem(reply, 0), &fast->terminate);
        return take_reply(fast, FAST_STORE, p_PyTuple_GetItem(reply, 1));
    }
    if (size < 0) {
        p_PyErr_Clear();
        return p_PyLong_AsLong(reply);
    }
    struct part part[4];
    int parts = destinations(fast, method, part);
    long expected = 0, taken = 0;
    for (int k = 0; k < parts; k++)
        expected += part[k].count;
    for (Py_ssize_t item = 1; item < size; item++) {
        PyObject *values = p_PyTuple_GetItem(reply, item);
        Py_ssize_t count = p_PyTuple_Size(values);
        if (count < 0 || count > expected - taken)
            return -1;
        double *scratch = fast->scratch + taken;
        for (Py_ssize_t i = 0; i < count; i++) {
            scratch[i] = p_PyFloat_AsDouble(p_PyTuple_GetItem(values, i));
            if (scratch[i] == -1.0 && p_PyErr_Occurred())
                return -1;
        }
        taken += count;
    }
    if (size < 2 || taken != expected)
        return -1;
    for (int k = 0, at = 0; k < parts; at += part[k].count, k++)
        memcpy(part[k].into, fast->scratch + at, (size_t)part[k].count * sizeof(double));
    return p_PyLong_AsLong(p_PyTuple_GetItem(reply, 0));
}

/* Before any call into the slave but a step (fast_do_step takes the inputs
 * itself): it takes what the steps in C left and the host's latest inputs; -1
 * when it could not catch up. */
int fast_before(struct instance *in)
{
    struct fast_path *fast = in->fast;
    if (!fast)
        return 0;
    if (catch_up(in))
        return -1;
    if (!fast->inputs_written)
        return 0;
    fast_call(in, FAST_LOAD);
    fast->inputs_written = 0;
    return 0;
}

/* After any call into the slave but a step (fast_do_step stores itself): it
 * may have changed inputs or parameters; the outputs stale.  The store's status. */
long fast_after(struct instance *in)
{
    struct fast_path *fast = in->fast;
    if (!fast)
        return fmi2OK;
    fast->stale = 1;
    return fast_call(in, FAST_STORE);
}

/* Call only when fast_serves(in, vr, n, 1); value holds every element in order. */
void fast_set(struct instance *in, const unsigned vr[], size_t n, const double value[])
{
    struct fast_path *fast = in->fast;
    for (size_t i = 0; i < n; i++) {
        long long at = single_index(fast, vr[i]);
        if (at >= 0) {
            fast->flat[at] = *value++;
            continue;
        }
        const long long *indices;
        long long count = flat_of(fast, vr[i], &indices);
        for (long long k = 0; k < count; k++)
            fast->flat[indices[k]] = *value++;
    }
    fast->stale = fast->inputs_written = 1;
}

/* Call only when fast_serves(in, vr, n, 0); the status getReal would return. */
fmi2Status fast_get(struct instance *in, const unsigned vr[], size_t n, double value[])
{
    struct fast_path *fast = in->fast;
    long status = fmi2OK;
    if (fast->stale) {
        fast->reading = vr, fast->reading_count = n;
        status = fast_call(in, FAST_OUTPUTS);
        fast->reading = NULL, fast->reading_count = 0;
        fast->inputs_written = 0;
        /* Held outputs (warning) are evaluated, and warned about, at every read. */
        fast->stale = status != fmi2OK;
    }
    for (size_t i = 0; i < n; i++) {
        long long at = single_index(fast, vr[i]);
        if (at >= 0) {
            *value++ = fast->flat[at];
            continue;
        }
        const long long *indices;
        long long count = flat_of(fast, vr[i], &indices);
        for (long long k = 0; k < count; k++)
            *value++ = fast->flat[indices[k]];
    }
/* pythonfmu's getReal answers OK: the warning is in the log (leave() sees it). */
    return status == fmi2Warning ? fmi2OK : (fmi2Status)status;
}

/* Whether an output of the step just taken in C is past its armed watch limit
 * (as `framework.watches.any_passed` compares: NaN passes none). */
static int watch_passed(const struct fast_path *fast)
{
    for (long k = 0; k < fast->outputs; k++)
        if (fabs(fast->values[k]) > fast->limits[k])
            return 1;
    return 0;
}

/* doStep: in C when the generated step takes it (the slave catches up at its
 * next call, or at once to warn of a watch passed), else by the slave in one
 * call, fast_do_step: the host's inputs when written, its do_step, then what
 * fast_store gives (what fast_before and fast_after do around any other call,
 * in one entry into Python); a step it takes leaves its outputs in the
 * arrays, fresh.  `terminate` (may be NULL) as the slave says. */
fmi2Status fast_step(struct instance *in, double time, double step, int *terminate)
{
    struct fast_path *fast = in->fast;
    if (fast && fast->generated && generated_take(fast, time, step)) {
        in->last_successful_time = fast->behind_time = time + step;
        fast->behind = 1;
        fast->inputs_written = fast->stale = 0;
        /* The slave warns once, as after a step in Python; the step stands. */
        return watch_passed(fast) ? (fmi2Status)fast_call(in, FAST_WATCH) : fmi2OK;
    }
    if (!fast)
        return slave_do_step(in, time, step, terminate);
    fast->step_time = time, fast->step_size = step;
    fast->answer = fmi2Error; /* unless do_step answers */
    fast->terminate = 0;
    long stored = fast_call(in, FAST_STEP);
    fmi2Status status = fast->answer;
    fast->inputs_written = 0;
    fast->stale = stored != fmi2OK || status != fmi2OK;
    in->last_successful_time = status == fmi2OK ? time + step : time;
    if (terminate)
        *terminate = fast->terminate;
    return status;
}
