/* Call-order fuzz of the C ABI: COUNT random fmi2 calls, legal and illegal, on
 * one instance.  The host keeps its own model of the FMI 2.0 co-simulation state
 * machine to know which calls are illegal.  Checks: the process survives; every
 * illegal call returns fmi2Discard or worse and logs at least one message;
 * every call that returns fmi2Discard or worse logs one; no call ends in
 * fmi2Fatal.  Afterwards fmi2Reset and a legal run give the same outputs as a
 * fresh instance.  Prints a summary; exits 1 on the first violation. */
#include "host.h"

#include <math.h>
#include <string.h>

enum { INSTANTIATED, INITIALIZATION, STEP_COMPLETE, TERMINATED };

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
static fmi2FMUstate live[MAX_STATES], freed[MAX_STATES];
static int n_live, n_freed;
/* Whether the slave has left initialization; each live state carries it, and
 * setting a state that has puts the instance in step mode (Reference-FMUs). */
static int slave_initialized, live_initialized[MAX_STATES];

/* A new state may come back at the address of a freed one. */
static void keep_live(fmi2FMUstate state, int initialized)
{
    live_initialized[n_live] = initialized;
    live[n_live++] = state;
    for (int k = 0; k < n_freed; k++)
        if (freed[k] == state)
            freed[k--] = freed[--n_freed];
}

static void verdict(const char *call, int illegal, fmi2Status status, int logged)
{
    n_calls++;
    n_illegal += illegal;
    if (status >= fmi2Fatal || (illegal && status < fmi2Discard) || (status >= fmi2Discard && !logged)) {
        printf("call %d (%s, %s): status %d, %d messages\n", n_calls, call,
               illegal ? "illegal" : "legal", status, logged);
        exit(1);
    }
}

static void legal_run(fmi2Component c, double *result, int n_out, const fmi2ValueReference *out)
{
    fmi2ValueReference in[2] = {reference("input_speed"), reference("bend_angle")};
    double values[2] = {12.0, 0.4};
    check(fmu.SetupExperiment(c, fmi2False, 0.0, 0.0, fmi2False, 0.0), "SetupExperiment");
    initialize(c);
    for (int k = 0; k < 20; k++) {
        check(fmu.SetReal(c, in, 2, values), "SetReal");
        check(fmu.DoStep(c, k * 1e-3, 1e-3, fmi2True), "DoStep");
    }
    check(fmu.GetReal(c, out, n_out, result), "GetReal");
}

int fuzz(const char *dir, unsigned seed, int count)
{
    load(dir);
    rng = seed;
    fmi2Component c = fmu.Instantiate("fuzz", fmi2CoSimulation, fmu.guid, fmu.resources,
                                      &callbacks, fmi2False, fmi2False);
    if (!c)
        fail("fmi2Instantiate returned NULL");
    int state = INSTANTIATED, n_out;
    double time = 0.0, values[8], foreign_state = 0;
    fmi2ValueReference out[64], vr[8];
    n_out = outputs(out);
    int n_variables = fmu.n_variables, first_output = n_variables - n_out;

    for (int i = 0; i < count; i++) {
        int before = log_calls, illegal = 0, which = pick(16);
        fmi2Status status = fmi2OK;
        const char *call = "";
        size_t n = 1 + pick(3);
        for (size_t k = 0; k < n; k++) {
            vr[k] = pick(n_variables + 4);        /* a few beyond the last one */
            values[k] = pick(3) ? 0.05 * pick(20) : NASTY[pick(10)];
        }
        switch (which) {
        case 0:
            call = "SetupExperiment";
            illegal = state != INSTANTIATED;
            status = fmu.SetupExperiment(c, fmi2False, 0.0, 0.0, fmi2False, 0.0);
            time = 0.0;
            break;
        case 1:
            call = "EnterInitializationMode";
            illegal = state != INSTANTIATED;
            status = fmu.EnterInitializationMode(c);
            if (!illegal)
                state = INITIALIZATION;
            break;
        case 2:
            call = "ExitInitializationMode";
            illegal = state != INITIALIZATION;
            status = fmu.ExitInitializationMode(c);
            if (!illegal)
                state = STEP_COMPLETE, slave_initialized = 1;
            break;
        case 3: case 4: {
            call = "SetReal";
            illegal = state == TERMINATED;
            /* Value reference r is the r-th variable (1-based): 0 names none. */
            for (size_t k = 0; k < n; k++)
                illegal |= vr[k] == 0 || (int)vr[k] > first_output ||
                           (state == STEP_COMPLETE && vr[k] > 6);  /* parameters are fixed */
            status = fmu.SetReal(c, vr, n, values);
            break;
        }
        case 5:
            call = "GetReal";
            for (size_t k = 0; k < n; k++)
                illegal |= vr[k] == 0 || (int)vr[k] > n_variables;
            status = fmu.GetReal(c, vr, n, values);
            break;
        case 6: case 7: {
            call = "DoStep";
            double step = pick(2) ? 1e-3 : NASTY[pick(10)];
            illegal = state != STEP_COMPLETE || !(step > 0.0) || isinf(step) || step > 1e15;
            status = fmu.DoStep(c, time, step, fmi2True);
            if (status == fmi2OK)
                time += step;
            break;
        }
        case 8:
            call = "Terminate";
            illegal = state != STEP_COMPLETE;
            status = fmu.Terminate(c);
            if (!illegal)
                state = TERMINATED;
            break;
        case 9:
            call = "Reset";
            status = fmu.Reset(c);
            state = INSTANTIATED, slave_initialized = 0;
            time = 0.0;
            break;
        case 10:
            call = "GetFMUstate";
            if (n_live == MAX_STATES)
                break;
            fmi2FMUstate s = NULL;
            status = fmu.GetFMUstate(c, &s);
            if (s)
                keep_live(s, slave_initialized);
            break;
        case 11: case 12: {
            int kind = pick(4);  /* live, freed, foreign, NULL */
            int index = n_live ? pick(n_live) : 0;
            fmi2FMUstate s = kind == 0 && n_live ? live[index]
                           : kind == 1 && n_freed ? freed[pick(n_freed)]
                           : kind == 2 ? (fmi2FMUstate)&foreign_state : NULL;
            illegal = !(kind == 0 && n_live);
            if (which == 11) {
                call = "SetFMUstate";
                status = fmu.SetFMUstate(c, s);
                if (!illegal && status <= fmi2Warning) {
                    slave_initialized = live_initialized[index];
                    if (slave_initialized)
                        state = STEP_COMPLETE;
                }
            } else {
                call = "FreeFMUstate";
                illegal &= s != NULL;              /* freeing NULL is a legal no-op */
                status = fmu.FreeFMUstate(c, &s);
                if (!illegal && kind == 0 && n_live) {
                    if (n_freed < MAX_STATES)
                        freed[n_freed++] = live[index];
                    live_initialized[index] = live_initialized[n_live - 1];
                    live[index] = live[--n_live];
                }
            }
            break;
        }
        case 13: {
            call = "SerializeFMUstate";
            if (!n_live)
                break;
            size_t size = 0;
            static char bytes[1 << 16];
            status = fmu.SerializedFMUstateSize(c, live[pick(n_live)], &size);
            if (status == fmi2OK && size <= sizeof bytes) {
                int from = (int)pick(n_live);
                fmi2FMUstate s = live[from];
                fmu.SerializedFMUstateSize(c, s, &size);
                status = fmu.SerializeFMUstate(c, s, bytes, size);
                if (pick(2))
                    bytes[pick((unsigned)size)] ^= 0x5a; /* a damaged copy */
                fmi2FMUstate copy = NULL;
                if (status == fmi2OK && n_live < MAX_STATES &&
                    fmu.DeSerializeFMUstate(c, bytes, size, &copy) <= fmi2Warning)
                    keep_live(copy, live_initialized[from]);
            }
            break;
        }
        case 14: {
            call = "no-such-call";
            illegal = 1;
            fmi2Integer integer;
            fmi2Status kind;
            switch (pick(4)) {
            case 0: status = fmu.GetInteger(c, vr, 1, &integer); break;
            case 1: status = fmu.CancelStep(c); break;
            case 2: status = fmu.GetStatus(c, fmi2DoStepStatus, &kind); break;
            default: status = fmu.SetReal(c, vr, 2, NULL); break;
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

    double after[64], fresh[64];
    check(fmu.Reset(c), "Reset");
    legal_run(c, after, n_out, out);
    fmi2Component other = fmu.Instantiate("fresh", fmi2CoSimulation, fmu.guid, fmu.resources,
                                          &callbacks, fmi2False, fmi2False);
    legal_run(other, fresh, n_out, out);
    int same = memcmp(after, fresh, n_out * sizeof(double)) == 0;
    for (int k = 0; k < n_live; k++)
        check(fmu.FreeFMUstate(c, &live[k]), "FreeFMUstate");
    fmu.FreeInstance(c);
    fmu.FreeInstance(other);
    printf("fuzz %d calls, %d illegal, all answered; after reset %s a fresh instance\n",
           n_calls, n_illegal, same ? "equal to" : "DIFFERENT FROM");
    return same ? 0 : 1;
}
