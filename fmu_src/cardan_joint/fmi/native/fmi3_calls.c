/* The fmi3 functions after instantiate, through the slave's Python methods
 * (slave_object.c, slave_values.c) as pythonfmu3 0.3.4 called them, behind the
 * checks the FMI 2.0 calls make (fmi2_calls.c): the instance, the
 * co-simulation state machine (no event mode: Instantiated -> Initialization
 * -> Step -> Terminated), arrays given, and value references and value counts
 * that match the variable record (resources/variables.txt, checked against the
 * slave at instantiate) and fixed parameters after initialization (the rest of
 * what may be set when stays the slave's check, in Python).
 * A call that fails a check is answered with fmi3Error and a message without
 * reaching Python, and changes nothing. */
#include "fmi3_instance.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>


int values_fit(struct instance3 *in3, const char *function, enum value_type type,
               const fmi3ValueReference vr[], size_t nvr, const void *values, size_t n_values,
               int setting)
{
    struct instance *in = &in3->base;
    if (!arrays_given(in, function, nvr, vr, values))
        return 0;
    size_t expected = 0;
    int fixed = 0;
    for (size_t i = 0; i < nvr; i++) {
        const struct variable *v = find_variable(in3->variables, vr[i]);
        const char *refusal = !v                  ? "is not a variable of this FMU"
                              : v->type != type   ? "is of another type"
                              : v->size == 0      ? "has a structural size, not supported"
                              : v->size > (size_t)-1 - expected ? "makes the count wrap around"
                                                                 : NULL;
        /* even if a restored FMU state makes the slave think otherwise */
        fixed |= setting && !refusal && v->fixed && in->state == STATE_STEP_COMPLETE;
        if (refusal) {
            reportf(in, fmi2Error, "%s: value reference %u%s%s%s%s%s %s; the call was ignored",
                    function, vr[i], v ? " (" : "", v ? v->name : "", v ? ", " : "",
                    v ? TYPE_NAMES[v->type] : "", v ? ")" : "", refusal);
            return 0;
        }
        expected += v->size;
    }
    if (expected != n_values) {
        reportf(in, fmi2Error, "%s: nValues is %zu but the %zu value references hold %zu values; "
                "the call was ignored", function, n_values, nvr, expected);
        return 0;
    }
    return fixed ? 2 : 1;
}

static fmi3Status set_float64(struct instance *in, const fmi3ValueReference vr[], size_t nvr,
                              const fmi3Float64 values[], size_t n_values);

/* A batch with fixed parameters in step mode: each fixed one is refused by
 * name, every other value is set (as Reference-FMUs' setters go value by
 * value), and the call answers fmi3Error (docs/fmi-tools.md, "Batch sets").
 * values_fit has checked the references and the count. */
static fmi3Status set_all_but_fixed(struct instance3 *in3, const fmi3ValueReference vr[],
                                    size_t nvr, const fmi3Float64 values[], size_t n_values)
{
    struct instance *in = &in3->base;
    fmi3ValueReference *kept_vr = malloc(nvr * sizeof *kept_vr);
    fmi3Float64 *kept_values = malloc((n_values ? n_values : 1) * sizeof *kept_values);
    size_t kept = 0, kept_n = 0, at = 0, fixed = 0;
    for (size_t i = 0; i < nvr; i++)
        fixed += find_variable(in3->variables, vr[i])->fixed;
    if (!kept_vr || !kept_values) {
        free(kept_vr), free(kept_values);
        reportf(in, fmi2Error, "fmi3SetFloat64: out of memory; the call was ignored");
        return fmi3Error;
    }
    for (size_t i = 0; i < nvr; i++) {
        const struct variable *v = find_variable(in3->variables, vr[i]);
        if (v->fixed) {
            reportf(in, fmi2Error, "fmi3SetFloat64: parameter %s is fixed: it can be set only "
                    "before fmi3ExitInitializationMode; its value was not set%s", v->name,
                    nvr > fixed ? " (the call's other values were)" : "");
        } else {
            kept_vr[kept++] = vr[i];
            memcpy(kept_values + kept_n, values + at, v->size * sizeof *values);
            kept_n += v->size;
        }
        at += v->size;
    }
    fmi3Status status = kept ? set_float64(in, kept_vr, kept, kept_values, kept_n) : fmi3OK;
    free(kept_vr), free(kept_values);
    return status > fmi3Error ? status : fmi3Error;
}

/* The slave's variables are Float64 (record_check.c holds the record to that):
 * an accessor of another type checks its arguments as every accessor does, so
 * any value reference is refused by name and an empty call succeeds. */
#define NO_VALUES3(get_or_set, Type, constness)                                     \
    fmi3Status fmi3##get_or_set##Type(fmi3Instance c, const fmi3ValueReference vr[],         \
                                      size_t nvr, constness fmi3##Type values[],             \
                                      size_t n_values)                                       \
    {                                                                                        \
        const char *function = "fmi3" #get_or_set #Type;                                     \
        struct instance *in = ENTER(c, fmi3##get_or_set##Type);                              \
        if (!in || !values_fit((struct instance3 *)in, function, T_##Type##_ID, vr, nvr,     \
                               values, n_values, 0))                                         \
            return fmi3Error;                                                                \
        if (nvr == 0)                                                                        \
            return fmi3OK;                                                                   \
        reportf(in, fmi2Error, "%s: the slave has Float64 variables only; the call was "     \
                "ignored", function);                                                        \
        return fmi3Error;                                                                    \
    }
#define NO_ACCESSORS(Type)                                                                   \
    NO_VALUES3(Get, Type, ) NO_VALUES3(Set, Type, const)
#define T_Float32_ID T_FLOAT32
#define T_Int8_ID T_INT8
#define T_UInt8_ID T_UINT8
#define T_Int16_ID T_INT16
#define T_UInt16_ID T_UINT16
#define T_Int32_ID T_INT32
#define T_UInt32_ID T_UINT32
#define T_Int64_ID T_INT64
#define T_UInt64_ID T_UINT64
#define T_Boolean_ID T_BOOLEAN
#define T_String_ID T_STRING
NO_ACCESSORS(Float32)
NO_ACCESSORS(Int8)
NO_ACCESSORS(UInt8)
NO_ACCESSORS(Int16)
NO_ACCESSORS(UInt16)
NO_ACCESSORS(Int32)
NO_ACCESSORS(UInt32)
NO_ACCESSORS(Int64)
NO_ACCESSORS(UInt64)
NO_ACCESSORS(Boolean)
NO_ACCESSORS(String)

/* Float64 values of inputs, parameters and outputs come from the fast
 * path's arrays when the instance has them (fast_path.c); time and the rest
 * go to the slave, as every value does without them. */
fmi3Status fmi3GetFloat64(fmi3Instance c, const fmi3ValueReference vr[], size_t nvr,
                          fmi3Float64 values[], size_t n_values)
{
    struct instance *in = ENTER(c, fmi3GetFloat64);
    if (!in || !values_fit((struct instance3 *)in, "fmi3GetFloat64", T_FLOAT64, vr, nvr, values,
                           n_values, 0))
        return fmi3Error;
    if (nvr == 0)
        return fmi3OK;
    if (fast_serves(in, vr, nvr, 0))
        return (fmi3Status)leave(in, fast_get(in, vr, nvr, values));
    if (fast_before(in))
        return (fmi3Status)leave(in, fmi2Error);
    fmi2Status status = leave(in, slave_get(in, "get_float64", 'd', vr, nvr, values, n_values));
    fast_after(in);
    return (fmi3Status)status;
}

static fmi3Status set_float64(struct instance *in, const fmi3ValueReference vr[], size_t nvr,
                              const fmi3Float64 values[], size_t n_values)
{
    if (fast_serves(in, vr, nvr, 1)) {
        fast_set(in, vr, nvr, values);
        return (fmi3Status)leave(in, fmi2OK);
    }
    if (fast_before(in))
        return (fmi3Status)leave(in, fmi2Error);
    fmi2Status status = leave(in, slave_set(in, "set_float64", 'd', vr, nvr, values, n_values));
    fast_after(in);
    return (fmi3Status)status;
}

fmi3Status fmi3SetFloat64(fmi3Instance c, const fmi3ValueReference vr[], size_t nvr,
                          const fmi3Float64 values[], size_t n_values)
{
    struct instance *in = ENTER(c, fmi3SetFloat64);
    int fit = in ? values_fit((struct instance3 *)in, "fmi3SetFloat64", T_FLOAT64, vr, nvr,
                              values, n_values, 1)
                 : 0;
    if (!fit)
        return fmi3Error;
    if (nvr == 0)
        return fmi3OK;
    if (fit == 2)
        return set_all_but_fixed((struct instance3 *)in, vr, nvr, values, n_values);
    return set_float64(in, vr, nvr, values, n_values);
}

/* --- life cycle --------------------------------------------------------------- */

fmi3Status fmi3SetDebugLogging(fmi3Instance c, fmi3Boolean on, size_t n,
                               const fmi3String categories[])
{
    struct instance *in = ENTER(c, fmi3SetDebugLogging);
    return in ? (fmi3Status)set_debug_logging(in, "fmi3SetDebugLogging", on, n, categories)
              : fmi3Error;
}

fmi3Status fmi3EnterInitializationMode(fmi3Instance c, fmi3Boolean tolerance_defined,
                                       fmi3Float64 tolerance, fmi3Float64 start,
                                       fmi3Boolean stop_defined, fmi3Float64 stop)
{
    /* pythonfmu3 0.3.4 passes none of these on: the slave's clock starts at 0 */
    (void)tolerance_defined, (void)tolerance, (void)start, (void)stop_defined, (void)stop;
    return (fmi3Status)transition(c, CALL(fmi3EnterInitializationMode), NULL,
                                  "enter_initialization_mode", STATE_INITIALIZATION);
}

fmi3Status fmi3ExitInitializationMode(fmi3Instance c)
{
    return (fmi3Status)transition(c, CALL(fmi3ExitInitializationMode), NULL,
                                  "exit_initialization_mode", STATE_STEP_COMPLETE);
}

fmi3Status fmi3Terminate(fmi3Instance c)
{
    return (fmi3Status)transition(c, CALL(fmi3Terminate), NULL, "terminate",
                                  STATE_TERMINATED);
}

fmi3Status fmi3Reset(fmi3Instance c)
{
    return (fmi3Status)transition(c, CALL(fmi3Reset), NULL, NULL, STATE_INSTANTIATED);
}

/* --- stepping ------------------------------------------------------------------- */

fmi3Status fmi3DoStep(fmi3Instance c, fmi3Float64 time, fmi3Float64 step,
                      fmi3Boolean no_set_prior, fmi3Boolean *event_handling_needed,
                      fmi3Boolean *terminate, fmi3Boolean *early_return,
                      fmi3Float64 *last_successful_time)
{
    struct instance *in = ENTER(c, fmi3DoStep);
    if (!in)
        return fmi3Error;
    if (!event_handling_needed || !terminate || !early_return || !last_successful_time) {
        report(in, fmi2Error, NULL, "fmi3DoStep got a NULL pointer for one of its four "
                                    "results; the call was ignored");
        return fmi3Error;
    }
    (void)no_set_prior;
    *event_handling_needed = *terminate = *early_return = fmi3False;
    int ends = 0;
    fmi2Status status = fast_step(in, time, step, &ends);
    *terminate = ends != 0;
    /* As pythonfmu3 answers: the step's end when taken, its start when not. */
    *last_successful_time = in->last_successful_time;
    return (fmi3Status)step_status(in, (fmi2Status)status);
}
