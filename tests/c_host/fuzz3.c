/* Call-order fuzz of the FMI 3.0 C ABI, as fuzz.c for FMI 2.0: COUNT random fmi3
 * calls, legal and illegal, on one instance.  The host keeps its own model of
 * the co-simulation state machine (no event mode) to know which calls are
 * illegal.  Checks: the process survives; every illegal call returns
 * fmi3Discard or worse and logs at least one message; every call that returns
 * fmi3Discard or worse logs one; no call ends in fmi3Fatal.  Afterwards
 * fmi3Reset and a legal run give the same outputs as a fresh instance. */
#include "host3.h"

#include <math.h>
#include <string.h>

enum { INSTANTIATED, INITIALIZATION, STEP_MODE, TERMINATED };

#define MAX_STATES 64

static unsigned rng;
static unsigned next_random(void)
{
    rng = rng * 1103515245u + 12345u;
    return (rng >> 8) & 0xffffff;
}
static unsigned pick(unsigned n) { return next_random() % n; }

static const double NASTY[] = {0.1, -0.2, 1e-3, 0.0, NAN, INFINITY, -INFINITY, 1e300, -1e300, 5e-324};

static int n_calls, n_illegal;
static fmi3FMUState live[MAX_STATES], freed[MAX_STATES];
static int n_live, n_freed;

/* Whether the slave has left initialization; each live state carries it, and
 * setting a state that has puts the instance in step mode (Reference-FMUs). */
static int slave_initialized, live_initialized[MAX_STATES];

/* A new state may come back at the address of a freed one. */
static void keep_live(fmi3FMUState state, int initialized)
{
    live_initialized[n_live] = initialized;
    live[n_live++] = state;
    for (int k = 0; k < n_freed; k++)
        if (freed[k] == state)
            freed[k--] = freed[--n_freed];
}

static void verdict(const char *call, int illegal, fmi3Status status, int logged)
{
    n_calls++;
    n_illegal += illegal;
    if (status >= fmi3Fatal || (illegal && status < fmi3Discard) ||
        (status >= fmi3Discard && !logged)) {
        printf("call %d (%s, %s): status %d, %d messages\n", n_calls, call,
               illegal ? "illegal" : "legal", status, logged);
        exit(1);
    }
}

static size_t outputs(fmi3ValueReference *vr, size_t *n_values)
{
    size_t n = 0;
    *n_values = 0;
    for (int i = 0; i < fmu.n_variables; i++)
        if (strcmp(fmu.variables[i].causality, "output") == 0) {
            vr[n++] = fmu.variables[i].vr;
            *n_values += (size_t)fmu.variables[i].size;
        }
    return n;
}

static void legal_run(fmi3Instance c, double *result)
{
    fmi3ValueReference in[2] = {variable("input_speed")->vr, variable("bend_angle")->vr}, out[64];
    double values[2] = {12.0, 0.4};
    initialize(c);
    for (int k = 0; k < 20; k++) {
        check(fmu.SetFloat64(c, in, 2, values, 2), "SetFloat64");
        check(step(c, k * 1e-3, 1e-3), "DoStep");
    }
    size_t n_values, n = outputs(out, &n_values);
    check(fmu.GetFloat64(c, out, n, result, n_values), "GetFloat64");
}

/* Values the references take; `exact` is 0 when the host asks for a wrong count. */
static size_t values_for(const fmi3ValueReference *vr, size_t n, int *known, int *exact)
{
    size_t total = 0;
    *known = 1;
    for (size_t k = 0; k < n; k++) {
        int found = 0;
        for (int i = 0; i < fmu.n_variables; i++)
            if (fmu.variables[i].vr == vr[k])
                total += (size_t)fmu.variables[i].size, found = 1;
        *known &= found;
    }
    *exact = pick(8) != 0;
    return *exact ? total : total + 1 - 2 * pick(2);
}

static const struct variable *of(fmi3ValueReference vr)
{
    for (int i = 0; i < fmu.n_variables; i++)
        if (fmu.variables[i].vr == vr)
            return &fmu.variables[i];
    return NULL;
}

int fuzz3(unsigned seed, int count)
{
    rng = seed;
    fmi3Instance c = start("fuzz");
    int state = INSTANTIATED;
    double time = 0.0, values[64], foreign_state = 0;
    fmi3ValueReference vr[8];
    for (int i = 0; i < count; i++) {
        int before = log_calls, illegal = 0, which = pick(16), known, exact;
        fmi3Status status = fmi3OK;
        const char *call = "";
        size_t n = 1 + pick(3);
        for (size_t k = 0; k < n; k++)
            vr[k] = pick((unsigned)fmu.n_variables + 4);  /* a few beyond the last one */
        size_t n_values = values_for(vr, n, &known, &exact);
        for (size_t k = 0; k < 64; k++)
            values[k] = pick(3) ? 0.05 * pick(20) : NASTY[pick(10)];
        switch (which) {
        case 0:
            call = "EnterInitializationMode";
            illegal = state != INSTANTIATED;
            status = fmu.EnterInitializationMode(c, fmi3False, 0.0, 0.0, fmi3False, 0.0);
            time = 0.0;
            if (!illegal)
                state = INITIALIZATION;
            break;
        case 1:
            call = "ExitInitializationMode";
            illegal = state != INITIALIZATION;
            status = fmu.ExitInitializationMode(c);
            if (!illegal)
                state = STEP_MODE, slave_initialized = 1;
            break;
        case 2: case 3:
            call = "SetFloat64";
            illegal = state == TERMINATED || !known || !exact || n_values > 64;
            for (size_t k = 0; k < n && !illegal; k++) {
                const char *causality = of(vr[k])->causality;
                illegal |= strcmp(causality, "input") != 0 &&
                           (strcmp(causality, "parameter") != 0 || state == STEP_MODE);
            }
            status = fmu.SetFloat64(c, vr, n, values, n_values > 64 ? 64 : n_values);
            break;
        case 4:
            call = "GetFloat64";
            illegal = !known || !exact || n_values > 64;
            status = fmu.GetFloat64(c, vr, n, values, n_values > 64 ? 64 : n_values);
            break;
        case 5: case 6: {
            call = "DoStep";
            double h = pick(2) ? 1e-3 : NASTY[pick(10)];
            illegal = state != STEP_MODE || !(h > 0.0) || isinf(h) || h > 1e15;
            status = step(c, time, h);
            if (status == fmi3OK)
                time += h;
            break;
        }
        case 7:
            call = "Terminate";
            illegal = state != STEP_MODE;
            status = fmu.Terminate(c);
            if (!illegal)
                state = TERMINATED;
            break;
        case 8:
            call = "Reset";
            status = fmu.Reset(c);
            state = INSTANTIATED, slave_initialized = 0;
            time = 0.0;
            break;
        case 9: {
            call = "GetFMUState";
            if (n_live == MAX_STATES)
                break;
            fmi3FMUState s = NULL;
            status = fmu.GetFMUState(c, &s);
            if (s)
                keep_live(s, slave_initialized);
            break;
        }
        case 10: case 11: {
            int kind = pick(4);  /* live, freed, foreign, NULL */
            int index = n_live ? pick(n_live) : 0;
            fmi3FMUState s = kind == 0 && n_live ? live[index]
                           : kind == 1 && n_freed ? freed[pick(n_freed)]
                           : kind == 2 ? (fmi3FMUState)&foreign_state : NULL;
            illegal = !(kind == 0 && n_live);
            if (which == 10) {
                call = "SetFMUState";
                status = fmu.SetFMUState(c, s);
                if (!illegal && status <= fmi3Warning) {
                    slave_initialized = live_initialized[index];
                    if (slave_initialized)
                        state = STEP_MODE;
                }
            } else {
                call = "FreeFMUState";
                illegal &= s != NULL;  /* freeing NULL is a legal no-op */
                status = fmu.FreeFMUState(c, &s);
                if (!illegal && kind == 0 && n_live) {
                    if (n_freed < MAX_STATES)
                        freed[n_freed++] = live[index];
                    live_initialized[index] = live_initialized[n_live - 1];
                    live[index] = live[--n_live];
                }
            }
            break;
        }
        case 12: {
            call = "SerializeFMUState";
            if (!n_live)
                break;
            size_t size = 0;
            static char bytes[1 << 16];
            int from = (int)pick(n_live);
            fmi3FMUState s = live[from];
            status = fmu.SerializedFMUStateSize(c, s, &size);
            if (status == fmi3OK && size <= sizeof bytes) {
                status = fmu.SerializeFMUState(c, s, bytes, size);
                if (pick(2))
                    bytes[pick((unsigned)size)] ^= 0x5a;  /* a damaged copy */
                fmi3FMUState copy = NULL;
                if (status == fmi3OK && n_live < MAX_STATES &&
                    fmu.DeserializeFMUState(c, bytes, size, &copy) <= fmi3Warning && copy)
                    keep_live(copy, live_initialized[from]);
            }
            break;
        }
        case 13: {
            call = "unsupported";
            illegal = 1;
            fmi3Int32 integer;
            float single;
            switch (pick(4)) {
            case 0: status = fmu.GetInt32(c, vr, 1, &integer, 1); break;
            case 1: status = fmu.EnterEventMode(c); break;
            case 2: status = fmu.GetFloat32(c, vr, 1, &single, 1); break;
            default: status = fmu.SetFloat64(c, vr, 2, NULL, 2); break;
            }
            break;
        }
        default:
            call = "SetDebugLogging";
            status = fmu.SetDebugLogging(c, pick(2), 0, NULL);
            break;
        }
        verdict(call, illegal, status, log_calls - before);
    }

    double after[256], fresh[256];
    check(fmu.Reset(c), "Reset");
    legal_run(c, after);
    fmi3Instance other = start("fresh");
    legal_run(other, fresh);
    fmi3ValueReference out[64];
    size_t n_values;
    outputs(out, &n_values);
    int same = memcmp(after, fresh, n_values * sizeof(double)) == 0;
    for (int k = 0; k < n_live; k++)
        check(fmu.FreeFMUState(c, &live[k]), "FreeFMUState");
    fmu.FreeInstance(c);
    fmu.FreeInstance(other);
    printf("fuzz %d calls, %d illegal, all answered; after reset %s a fresh instance\n",
           n_calls, n_illegal, same ? "equal to" : "DIFFERENT FROM");
    return same ? 0 : 1;
}
