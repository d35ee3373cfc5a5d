/* The fast path's per-instance arrays and Python objects (fast_path.c sets
 * them up and calls the slave, fast_values.c serves values and steps from them). */
#ifndef CARDAN_JOINT_FAST_PATH_H
#define CARDAN_JOINT_FAST_PATH_H

#include "instance.h"

/* The slave's methods, in the order fast_path.c looks them up. */
enum fast_method {
    FAST_OUTPUTS,
    FAST_LOAD,
    FAST_STORE,
    FAST_STEP,
    FAST_SYNC,
    FAST_WATCH,
    FAST_METHODS
};

struct fast_path {
    PyObject *slave, *methods[FAST_METHODS];
    PyObject *queue; /* the slave's log_queue: drained only when it holds a message */
    long inputs, known_size, first_output, outputs;
    int stale;          /* the outputs array is not current */
    int inputs_written; /* the slave has not taken the host's latest inputs yet */
    /* One block, flat[i] the value of flat index i: the known values (inputs,
     * parameters), then `values`, the outputs (first_output == known_size). */
    double *flat, *known, *values;
    double *scratch; /* the largest reply (fast_store's), converted before it is written */
    /* The generated step (generated_step.c, docs/codegen.md), when the build
     * compiled one in and the slave hands over its step state: state_size
     * doubles of state; arguments (t, h, state, known) and results (state,
     * moved inputs, outputs); `held` the last step's moved inputs.  `behind`:
     * steps were taken in C since the slave last saw the state (fast_sync), the
     * last one ending at behind_time. */
    int generated, behind;
    long state_size;
    double *state, *arguments, *results, *held, behind_time;
    /* A step the slave takes (fast_do_step): its time and size, and its
     * do_step's answer and terminateSimulation, as slave_do_step reads them. */
    double step_time, step_size;
    fmi2Status answer;
    int terminate;
    /* With the generated step: each output's armed watch limit (+inf: none),
     * from fast_store; a step taken in C whose output passes one hands over to
     * the slave (fast_watch), which warns once and disarms it. */
    double *limits;
    /* The slave's value references (its fast_flat, both FMI versions):
     * {n, start[0..n], indices...}: value reference vr < n holds the flat
     * indices indices[start[vr]] to indices[start[vr + 1] - 1]. */
    long long *table;
    /* Each value reference's SERVES_* flags, set once when the table is
     * taken, so that a call's references are checked by a look-up each
     * instead of a walk over their indices. */
    unsigned char *serves;
    /* Each value reference's one flat index, or -1 when it has none or
     * several (flat_of then); most have one, read without a loop. */
    long long *single;
    /* The value references a getReal reads, while it asks fast_outputs. */
    const unsigned *reading;
    size_t reading_count;
};

/* Whether the slave's layout holds counts the arrays can take: else said (a
 * Warning), and its values go through plain calls. */
int sizes_taken(struct instance *in, const struct fast_path *fast);
int fast_table(struct fast_path *fast, const char *bytes, size_t size);
/* The one flat index of value reference vr, or -1 (flat_of then); only for a
 * reference fast_serves has taken. */
static inline long long single_index(const struct fast_path *fast, unsigned vr)
{
    return fast->single[vr];
}
/* A value reference's flags in fast->serves: it has flat indices (all within
 * the arrays, as fast_table checked), and they are all inputs. */
enum { SERVES_VALUE = 1, SERVES_INPUT = 2 };
/* The flat indices of value reference vr, and how many (0: none).  Inline:
 * every Real read and input write takes it once per reference. */
static inline long long flat_of(const struct fast_path *fast, unsigned vr,
                                const long long **indices)
{
    const long long *table = fast->table;
    if (vr >= (unsigned long long)table[0])
        return 0; /* FMI 3's time, or a reference the slave does not have */
    const long long *start = table + 1;
    *indices = start + table[0] + 1 + start[vr];
    return start[vr + 1] - start[vr];
}
long fast_call(struct instance *in, enum fast_method method);
/* The generated step: 1 when it took the step (the arrays written), 0 when the
 * slave must (generated_step.c, compiled in only with the model's step). */
int generated_take(struct fast_path *fast, double time, double step);
/* Sizes the arrays of the generated step; 0 (none used) when its sizes do not
 * match the slave's layout. */
int generated_attach(struct fast_path *fast);
/* 1 when the build compiled the model's step in (the slave is asked for its state). */
int generated_compiled(void);
/* Before any call into the slave: it takes what the steps taken in C left; -1
 * when it could not (the instance then in STATE_ERROR, said). */
int catch_up(struct instance *in);
/* With the GIL: n doubles as a new tuple of floats (NULL: no memory). */
PyObject *tuple_of(const double *values, long n);
/* With the GIL: the flat indices of the value references being read
 * (fast->reading), in order, as a tuple of ints (NULL: no memory). */
PyObject *read_indices(const struct fast_path *fast);
/* With the GIL: the status of a method's reply, its values written into the
 * arrays; -1 when it is malformed (nothing written). */
long take_reply(struct fast_path *fast, enum fast_method method, PyObject *reply);

#endif
