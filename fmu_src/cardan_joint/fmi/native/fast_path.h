/* The one-call step's per-instance arrays and Python objects (fast_path.c
 * sets them up and calls the slave, fast_values.c serves values from them). */
#ifndef CARDAN_JOINT_FAST_PATH_H
#define CARDAN_JOINT_FAST_PATH_H

#include "instance.h"

/* The slave's methods, in the order fast_path.c looks them up. */
enum fast_method { FAST_STEP, FAST_OUTPUTS, FAST_LOAD, FAST_STORE };

struct fast_path {
    PyObject *slave, *methods[4];
    PyObject *queue; /* the slave's log_queue: drained only when it holds a message */
    /* The last call's inputs tuple and step size: a value a host leaves as it
     * was (a steady input, a fixed step) crosses again as the same object. */
    PyObject *last_inputs, *last_step;
    long inputs, known_size, first_output, outputs;
    int stale;          /* the outputs array is not current */
    int inputs_written; /* the slave has not taken the host's latest inputs yet */
    double *known, *values;
    double *scratch; /* outputs + known_size: a reply converted before it is written */
    /* FMI 3 (NULL for FMI 2, whose value references are the flat indices):
     * {n, start[0..n], indices...}: value reference vr < n holds the flat
     * indices indices[start[vr]] to indices[start[vr + 1] - 1]. */
    long long *table;
};

int fast_table(struct fast_path *fast, const char *bytes, size_t size);
/* The flat indices of value reference vr, and how many (0: none). */
long long flat_of(const struct fast_path *fast, unsigned vr, const long long **indices,
                  long long *own);
long fast_call(struct instance *in, enum fast_method method, double time, double step);
/* With the GIL: a float of `value`, `last` itself (a reference added) when it
 * holds the same bits; NULL: no memory. */
PyObject *float_like(PyObject *last, double value);
/* With the GIL: *slot holds `value` (a reference of its own) for the next call,
 * the object it held before released. */
void keep(PyObject **slot, PyObject *value);
/* With the GIL: the inputs (known[0..inputs)) as a tuple, kept as last_inputs. */
PyObject *inputs_tuple(struct fast_path *fast);
/* With the GIL: the status of a method's reply, its values written into the
 * arrays; -1 when it is malformed (nothing written). */
long take_reply(struct fast_path *fast, enum fast_method method, PyObject *reply);

#endif
