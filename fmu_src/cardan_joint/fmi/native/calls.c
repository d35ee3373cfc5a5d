/* What every call on an instance does first and last, for FMI 2.0 and 3.0:
 * check the instance and the co-simulation state machine (where() says, per
 * FMI version, what the host should have called), enter Python's thread state
 * for this host thread, and return the worst status logged during the call. */
#define _GNU_SOURCE
#include "instance.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

struct instance *enter(fmi2Component c, unsigned allowed, const char *function)
{
    struct instance *in = c;
    if (!in || in->magic != INSTANCE_MAGIC)
        return NULL;
    in->worst = fmi2OK;
    if (!(in->state & allowed)) {
        reportf(in, fmi2Error, "%s is not allowed %s; the call was ignored", function,
                where(in->state));
        return NULL;
    }
    if (enter_python_thread()) {
        reportf(in, fmi2Error, "%s: %s is not running any more (the host finalized it): the "
                "instance's slave is gone; the call was ignored", function, python_in_use());
        return NULL;
    }
    return in;
}

fmi2Status leave(struct instance *in, fmi2Status status)
{
    if (status == fmi2Fatal)
        in->state = STATE_FATAL;
    return status > in->worst ? status : in->worst;
}

/* Setting an FMU state taken in step mode puts the instance in step mode, as
 * Reference-FMUs do: fmusim's --initial-fmu-state-file sets one into an
 * instance it never initialized, then steps. */
void restore_mode(struct instance *in, fmi2Status status)
{
    if (status <= fmi2Warning && in->state != STATE_FATAL && slave_initialized(in) == 1)
        in->state = STATE_STEP_COMPLETE;
}

/* A refused step (the slave's Discard: it kept its state and logged variable,
 * value, limit and time) is answered with Error in both FMI versions, so that
 * every master ends the run as a failure: FMI 2.0 masters take Discard as
 * "retry" or, with fmi2Terminated, as a normal end (fmusim, FMUComplianceChecker).
 * The instance stays in step mode with its state: a master that corrects its
 * inputs (or sets an earlier FMU state) steps on as if nothing happened
 * (docs/fmi-tools.md, "Refused steps"). */
fmi2Status step_status(struct instance *in, fmi2Status status)
{
    status = leave(in, status);
    return status == fmi2Discard ? fmi2Error : status;
}

int arrays_given(struct instance *in, const char *function, size_t n,
                        const void *references, const void *values)
{
    if (n == 0 || (references && values))
        return 1;
    reportf(in, fmi2Error, "%s got a NULL array for %zu values; the call was ignored",
            function, n);
    return 0;
}


/* The loader keeps the host's logging choice; the slave always logs to it. */
fmi2Status set_debug_logging(struct instance *in, const char *function, int on, size_t n,
                             const char *const categories[])
{
    if (!arrays_given(in, function, n, categories, categories))
        return fmi2Error;
    char **copies = n ? calloc(n, sizeof *copies) : NULL;
    for (size_t i = 0; copies && i < n; i++)
        copies[i] = copy_of(categories[i]);
    for (size_t i = 0; i < in->n_categories; i++)
        free(in->categories[i]);
    free(in->categories);
    in->categories = copies;
    in->n_categories = copies ? n : 0;
    in->logging_on = on;
    return fmi2OK;
}

/* What instantiate does alike in both FMI versions, on a zeroed instance that
 * has its host's callbacks (`logger`: the host's logging function): the
 * instance's own fields, its slave constructed, the fast path set up and
 * the variable record checked against the slave.  The instance, or NULL (the
 * reason logged, the instance freed). */
struct instance *start_instance(struct instance *in, const char *name, const char *guid,
                                const char *location, const char *resources, int visible,
                                int logging_on, void *logger)
{
    char error[2048];
    in->magic = INSTANCE_MAGIC;
    in->model = MODEL_IDENTIFIER;
    in->name = copy_of(name);
    in->guid = copy_of(guid);
    in->resources_uri = copy_of(location);
    in->resources = copy_of(resources);
    in->last_successful_time = NAN;
    in->visible = visible;
    in->logging_on = logging_on;
    const char *echo = getenv(ENV_STDERR);
    in->echo_stderr = echo && *echo && strcmp(echo, "0") != 0;
    in->shared_proxy = is_shared_proxy(logger);
    in->state = STATE_INSTANTIATED;
    if (slave_construct(in, resources)) {
        reportf(in, fmi2Error, "the slave could not be instantiated in %s: see the message "
                "before", python_in_use());
        free_instance(in);
        return NULL;
    }
    fast_attach(in);
    if (record_matches_slave(in, resources, error, sizeof error)) {
        report(in, fmi2Error, NULL, error);
        free_instance(in);
        return NULL;
    }
    return in;
}

/* Reset: a fresh slave object (its constructor, run again), as pythonfmu's and
 * pythonfmu3's reset did; Error (the old slave kept) when it cannot be made. */
fmi2Status reset_slave(struct instance *in)
{
    fmi2Status status = slave_construct(in, in->resources) ? fmi2Error : fmi2OK;
    in->last_successful_time = NAN;
    fast_reset(in);
    return status;
}

/* A change of mode through the slave's `method` (NULL: reset), after `first`
 * (may be NULL); the instance enters `next` unless the call failed fatally. */
fmi2Status transition(void *c, unsigned allowed, const char *function,
                      fmi2Status (*first)(struct instance *), const char *method, enum state next)
{
    struct instance *in = enter(c, allowed, function);
    if (!in)
        return fmi2Error;
    enum state was = in->state;
    if (fast_before(in))
        return leave(in, fmi2Error);
    fmi2Status status = first ? first(in) : fmi2OK;
    if (status == fmi2OK)
        status = method ? slave_call(in, method) : reset_slave(in);
    status = leave(in, status);
    fast_after(in);
    /* unless the call left the instance fatal, or in error (an interrupted slave) */
    if (status <= fmi2Error && in->state == was)
        in->state = next;
    return status;
}

void free_instance(struct instance *in)
{
    fast_detach(in);
    /* drop_state moves the book's last entry into the freed slot and clears the
     * pointer it is given: hand it a copy, never a slot of the book itself. */
    while (in->n_fmu_states) {
        fmi2FMUstate state = in->fmu_states[0];
        drop_state(in, &state);
    }
    slave_release(in);
    for (size_t i = 0; i < in->n_categories; i++)
        free(in->categories[i]);
    in->magic = 0;
    free(in->categories);
    free(in->fmu_states);
    free(in->name);
    free(in->guid);
    free(in->resources_uri);
    free(in->resources);
    free(in);
}

char *copy_of(const char *text)
{
    return strdup(text ? text : "");
}
