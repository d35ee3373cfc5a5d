/* The fmi2 functions after fmi2Instantiate: each checks the instance and the
 * FMI 2.0 co-simulation state machine, enters Python's thread state for this
 * host thread, calls the slave's Python method (slave_object.c), and returns
 * the worst status logged.
 * A call the standard does not allow in the current state, on a NULL array or
 * on an FMU state this instance did not hand out is answered with fmi2Error and
 * a message, without reaching Python, and changes nothing. */
#define _GNU_SOURCE
#include "instance.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>


const char *where(enum state state)
{
    switch (state) {
    case STATE_INSTANTIATED:
        return "before initialization: call fmi2EnterInitializationMode and "
               "fmi2ExitInitializationMode first";
    case STATE_INITIALIZATION:
        return "in initialization mode: call fmi2ExitInitializationMode first";
    case STATE_STEP_COMPLETE:
        return "after initialization";
    case STATE_TERMINATED:
        return "after fmi2Terminate: call fmi2Reset to start again";
    case STATE_ERROR:
        return "after an error that left the slave out of step with the instance: call "
               "fmi2Reset to start again, or fmi2FreeInstance";
    default:
        return "after a fatal error: only fmi2FreeInstance is allowed";
    }
}

/* --- life cycle --------------------------------------------------------------- */

const char *fmi2GetTypesPlatform(void) { return "default"; }
const char *fmi2GetVersion(void) { return "2.0"; }

void fmi2FreeInstance(fmi2Component c)
{
    struct instance *in = ENTER(c, fmi2FreeInstance);
    if (in)
        free_instance(in);
}

fmi2Status fmi2SetDebugLogging(fmi2Component c, fmi2Boolean on, size_t n, const fmi2String categories[])
{
    struct instance *in = ENTER(c, fmi2SetDebugLogging);
    return in ? set_debug_logging(in, "fmi2SetDebugLogging", on, n, categories) : fmi2Error;
}

fmi2Status fmi2SetupExperiment(fmi2Component c, fmi2Boolean tolerance_defined, fmi2Real tolerance,
                               fmi2Real start, fmi2Boolean stop_defined, fmi2Real stop)
{
    struct instance *in = ENTER(c, fmi2SetupExperiment);
    if (!in)
        return fmi2Error;
    /* Kept for fmi2EnterInitializationMode, which passes it to the slave (as pythonfmu). */
    in->tolerance_defined = tolerance_defined, in->tolerance = tolerance;
    in->stop_defined = stop_defined, in->stop = stop;
    in->start = start;
    return leave(in, fmi2OK);
}

fmi2Status fmi2EnterInitializationMode(fmi2Component c)
{
    /* pythonfmu 0.7.0 sets the experiment up first, with fmi2SetupExperiment's values */
    return transition(c, CALL(fmi2EnterInitializationMode),
                      slave_setup_experiment, "enter_initialization_mode", STATE_INITIALIZATION);
}

fmi2Status fmi2ExitInitializationMode(fmi2Component c)
{
    return transition(c, CALL(fmi2ExitInitializationMode), NULL,
                      "exit_initialization_mode", STATE_STEP_COMPLETE);
}

fmi2Status fmi2Terminate(fmi2Component c)
{
    return transition(c, CALL(fmi2Terminate), NULL, "terminate",
                      STATE_TERMINATED);
}

/* Reset makes a fresh Python slave (reset_slave), as pythonfmu's did. */
fmi2Status fmi2Reset(fmi2Component c)
{
    return transition(c, CALL(fmi2Reset), NULL, NULL, STATE_INSTANTIATED);
}

/* --- values ------------------------------------------------------------------- */

#define VALUES(get_or_set, Type, member, kind, constness)                             \
    fmi2Status fmi2##get_or_set##Type(fmi2Component c, const fmi2ValueReference vr[],   \
                                      size_t n, constness fmi2##Type value[])            \
    {                                                                                    \
        const char *function = "fmi2" #get_or_set #Type;                                 \
        struct instance *in = ENTER(c, fmi2##get_or_set##Type);                          \
        if (!in || !arrays_given(in, function, n, vr, value))                            \
            return fmi2Error;                                                            \
        if (fast_before(in))                                                             \
            return leave(in, fmi2Error);                                                 \
        fmi2Status status = leave(in, slave_##get_or_set(in, #member, kind, vr, n, value, n)); \
        fast_after(in);                                                                  \
        return status;                                                                   \
    }
#define slave_Get slave_get
#define slave_Set slave_set
VALUES(Get, Integer, get_integer, 'i', )
VALUES(Get, Boolean, get_boolean, 'b', )
VALUES(Get, String, get_string, 's', )
VALUES(Set, Integer, set_integer, 'i', const)
VALUES(Set, Boolean, set_boolean, 'b', const)
VALUES(Set, String, set_string, 's', const)

/* After initialization a fixed parameter stays as it is, even if a restored FMU
 * state makes the slave believe it is not initialized yet. */
static const char *fixed_parameter(const struct instance *in, fmi2ValueReference vr)
{
    for (int k = 0; k < in->fixed->count; k++)
        if (in->fixed->parameters[k].vr == vr)
            return in->fixed->parameters[k].name;
    return NULL;
}

/* inputs_only: fast_serves(in, vr, n, 1), as the caller found it. */
static fmi2Status set_real(struct instance *in, const fmi2ValueReference vr[], size_t n,
                           const fmi2Real value[], int inputs_only)
{
    if (inputs_only) {
        fast_set(in, vr, n, value);
        return leave(in, fmi2OK);
    }
    if (fast_before(in))
        return leave(in, fmi2Error);
    fmi2Status status = leave(in, slave_set(in, "set_real", 'd', vr, n, value, n));
    fast_after(in);
    return status;
}

/* A batch with fixed parameters after initialization: each fixed one is refused
 * by name, every other value is set (as Reference-FMUs' setters go value by
 * value), and the call answers fmi2Error (docs/fmi-tools.md, "Batch sets"). */
fmi2Status fmi2SetReal(fmi2Component c, const fmi2ValueReference vr[], size_t n,
                       const fmi2Real value[])
{
    struct instance *in = ENTER(c, fmi2SetReal);
    if (!in || !arrays_given(in, "fmi2SetReal", n, vr, value))
        return fmi2Error;
    size_t kept = 0, refused = 0;
    /* Inputs only (the common call, every step) hold no fixed parameter. */
    int inputs_only = fast_serves(in, vr, n, 1);
    for (size_t i = 0; in->state == STATE_STEP_COMPLETE && !inputs_only && i < n; i++)
        refused += fixed_parameter(in, vr[i]) != NULL;
    if (!refused)
        return set_real(in, vr, n, value, inputs_only);
    fmi2ValueReference *kept_vr = malloc(n * sizeof *kept_vr);
    fmi2Real *kept_value = malloc(n * sizeof *kept_value);
    if (!kept_vr || !kept_value) {
        free(kept_vr), free(kept_value);
        reportf(in, fmi2Error, "fmi2SetReal: out of memory; the call was ignored");
        return fmi2Error;
    }
    for (size_t i = 0; i < n; i++) {
        const char *fixed = fixed_parameter(in, vr[i]);
        if (fixed)
            reportf(in, fmi2Error, "parameter %s is fixed: it can be set only before "
                    "fmi2ExitInitializationMode; %.17g was not set%s", fixed, value[i],
                    n > refused ? " (the call's other values were)" : "");
        else
            kept_vr[kept] = vr[i], kept_value[kept++] = value[i];
    }
    fmi2Status status =
        kept ? set_real(in, kept_vr, kept, kept_value, fast_serves(in, kept_vr, kept, 1)) : fmi2OK;
    free(kept_vr), free(kept_value);
    return status > fmi2Error ? status : fmi2Error;
}

fmi2Status fmi2GetReal(fmi2Component c, const fmi2ValueReference vr[], size_t n, fmi2Real value[])
{
    struct instance *in = ENTER(c, fmi2GetReal);
    if (!in || !arrays_given(in, "fmi2GetReal", n, vr, value))
        return fmi2Error;
    if (fast_serves(in, vr, n, 0))
        return leave(in, fast_get(in, vr, n, value));
    if (fast_before(in))
        return leave(in, fmi2Error);
    fmi2Status status = leave(in, slave_get(in, "get_real", 'd', vr, n, value, n));
    fast_after(in);
    return status;
}

/* --- stepping and status ------------------------------------------------------ */

fmi2Status fmi2DoStep(fmi2Component c, fmi2Real time, fmi2Real step, fmi2Boolean no_set_prior)
{
    struct instance *in = ENTER(c, fmi2DoStep);
    if (!in)
        return fmi2Error;
    (void)no_set_prior;
    return step_status(in, fast_step(in, time, step, NULL));
}

fmi2Status fmi2GetRealStatus(fmi2Component c, fmi2StatusKind kind, fmi2Real *value)
{
    struct instance *in = ENTER(c, fmi2GetRealStatus);
    if (!in || !arrays_given(in, "fmi2GetRealStatus", 1, value, value))
        return fmi2Error;
    if (kind == fmi2LastSuccessfulTime) {
        *value = in->last_successful_time;
        return leave(in, fmi2OK);
    }
    report(in, fmi2Error, NULL, "Invalid status inquiry for fmi2GetRealStatus");
    return fmi2Error;
}

fmi2Status fmi2GetBooleanStatus(fmi2Component c, fmi2StatusKind kind, fmi2Boolean *value)
{
    struct instance *in = ENTER(c, fmi2GetBooleanStatus);
    if (!in || !arrays_given(in, "fmi2GetBooleanStatus", 1, value, value))
        return fmi2Error;
    if (kind == fmi2Terminated) {
        *value = fmi2False;  /* the model never ends a run; a refused step is an error */
        return leave(in, fmi2OK);
    }
    report(in, fmi2Error, NULL, "Invalid status inquiry for fmi2GetBooleanStatus");
    return fmi2Error;
}
