/* A refused step in an fmusim-style FMI 2.0 loop (Reference-FMUs' fmusim: on
 * fmi2Discard it reads fmi2Terminated, ends normally when terminated and retries
 * the step when not; any status >= fmi2Error ends the run as a failure), then
 * the master restores the input and goes on: the outputs must equal a clean run
 * bit for bit.  Prints "fmusim: <verdict>" and "continued: identical|differs". */
#include "host.h"

#include <string.h>

#define STEPS 100
#define REFUSED_AT 50
#define H 1e-3

static void outputs_of(fmi2Component c, double *values, int *n)
{
    fmi2ValueReference out[64];
    *n = outputs(out);
    check(fmu.GetReal(c, out, *n, values), "GetReal");
}

int refusal(const char *dir, const char *name, double value)
{
    load(dir);
    fmi2ValueReference vr = reference(name);
    double clean[64], ours[64], valid;
    int n = 0, retries = 0;
    fmi2Component c = start("clean", fmi2False);
    initialize(c);
    for (int k = 0; k < STEPS; k++)
        check(fmu.DoStep(c, k * H, H, fmi2True), "DoStep");
    outputs_of(c, clean, &n);
    fmu.FreeInstance(c);

    c = start("refused", fmi2False);
    initialize(c);
    check(fmu.GetReal(c, &vr, 1, &valid), "GetReal");
    const char *verdict = "ran to the end";
    for (int k = 0; k < STEPS; k++) {
        if (k == REFUSED_AT)
            check(fmu.SetReal(c, &vr, 1, &value), "SetReal");
        fmi2Status status = fmu.DoStep(c, k * H, H, fmi2True);
        if (status == fmi2Discard) {
            fmi2Boolean terminated = fmi2False;
            fmu.GetBooleanStatus(c, fmi2Terminated, &terminated);
            if (terminated) {
                verdict = "ended normally (terminated)";
                break;
            }
            if (++retries > 100) {
                verdict = "retried the same step forever";
                break;
            }
            k--;
            continue;
        }
        if (status >= fmi2Error) {
            printf("fmusim: failed at t = %g with status %d: %s\n", k * H, status,
                   last_message);
            verdict = NULL;
            /* The master corrects its input and steps on from the same time. */
            check(fmu.SetReal(c, &vr, 1, &valid), "SetReal");
            check(fmu.DoStep(c, k * H, H, fmi2True), "DoStep after the correction");
        }
    }
    if (verdict)
        printf("fmusim: %s\n", verdict);
    outputs_of(c, ours, &n);
    printf("continued: %s\n", memcmp(clean, ours, n * sizeof *ours) ? "differs" : "identical");
    fmu.FreeInstance(c);
    return 0;
}
