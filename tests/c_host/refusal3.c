/* A refused step in an fmusim-style FMI 3.0 loop (any status > fmi3OK ends the
 * run as a failure), then the master restores the input and goes on: the
 * outputs must equal a clean run bit for bit (see refusal.c for FMI 2.0). */
#include "host3.h"

#include <string.h>

#define STEPS 100
#define REFUSED_AT 50
#define H 1e-3

static int outputs_of(fmi3Instance c, double *values)
{
    fmi3ValueReference out[64];
    int n = 0, count = 0;
    for (int i = 0; i < fmu.n_variables; i++)
        if (strcmp(fmu.variables[i].causality, "output") == 0) {
            out[n++] = fmu.variables[i].vr;
            count += fmu.variables[i].size;
        }
    check(fmu.GetFloat64(c, out, n, values, count), "GetFloat64");
    return count;
}

int refusal3(const char *name, double value)
{
    const struct variable *input = variable(name);
    double clean[256], ours[256], valid;
    fmi3Instance c = start("clean");
    initialize(c);
    for (int k = 0; k < STEPS; k++)
        check(step(c, k * H, H), "DoStep");
    int n = outputs_of(c, clean);
    fmu.FreeInstance(c);

    c = start("refused");
    initialize(c);
    check(fmu.GetFloat64(c, &input->vr, 1, &valid, 1), "GetFloat64");
    int failed = 0;
    for (int k = 0; k < STEPS; k++) {
        if (k == REFUSED_AT)
            check(fmu.SetFloat64(c, &input->vr, 1, &value, 1), "SetFloat64");
        fmi3Status status = step(c, k * H, H);
        if (status > fmi3OK) {
            printf("fmusim: failed at t = %g with status %d: %s\n", k * H, status,
                   last_message);
            failed = 1;
            check(fmu.SetFloat64(c, &input->vr, 1, &valid, 1), "SetFloat64");
            check(step(c, k * H, H), "DoStep after the correction");
        }
    }
    if (!failed)
        printf("fmusim: ran to the end\n");
    outputs_of(c, ours);
    printf("continued: %s\n", memcmp(clean, ours, n * sizeof *ours) ? "differs" : "identical");
    fmu.FreeInstance(c);
    return 0;
}
