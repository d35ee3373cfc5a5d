/* The model's step generated from its Python (docs/codegen.md), run on the
 * fast path's arrays: compiled with -DGENERATED_STEP beside the build's
 * generated_step.c, which defines generated_step and generated_step_sizes.
 * Without it (a model whose step runs in Python) every step goes to the
 * slave's do_step (fast_values.c's fast_step). */
#include "fast_path.h"

#include <stdlib.h>
#include <string.h>

#ifdef GENERATED_STEP
/* Arguments (t, h, state, known[0..n)), results (state, moved inputs,
 * outputs): 1 and the results written when the step is taken, 0 when the
 * slave must take or refuse it. */
int generated_step(const double *arguments, double *results);
/* {arguments read, results written} */
extern const long generated_step_sizes[2];
#endif

/* $CARDAN_JOINT_FMU_PYTHON_STEP=1 keeps every step in Python, to compare. */
int generated_compiled(void)
{
#ifdef GENERATED_STEP
    const char *python_step = getenv(ENV_PYTHON_STEP);
    return !(python_step && *python_step && strcmp(python_step, "0") != 0);
#else
    return 0;
#endif
}

int generated_attach(struct fast_path *fast)
{
#ifdef GENERATED_STEP
    /* The generated step reads a prefix of the known values (a build setting
     * may add parameters it does not use) and writes exactly the arrays. */
    long before_known = 2 + fast->state_size, arguments = generated_step_sizes[0];
    if (arguments < before_known + fast->inputs ||
        arguments > before_known + fast->known_size ||
        generated_step_sizes[1] != fast->state_size + fast->inputs + fast->outputs)
        return 0;
    double **buffers[3] = {&fast->arguments, &fast->results, &fast->held};
    long sizes[3] = {before_known + fast->known_size, generated_step_sizes[1], fast->inputs};
    for (int k = 0; k < 3; k++) {
        double *grown = realloc(*buffers[k], (size_t)(sizes[k] + 1) * sizeof *grown);
        if (!grown)
            return 0;
        *buffers[k] = grown;
    }
    return 1;
#else
    (void)fast;
    return 0;
#endif
}

int generated_take(struct fast_path *fast, double time, double step)
{
#ifdef GENERATED_STEP
    long state = fast->state_size, inputs = fast->inputs;
    double *arguments = fast->arguments;
    arguments[0] = time;
    arguments[1] = step;
    memcpy(arguments + 2, fast->state, (size_t)state * sizeof(double));
    memcpy(arguments + 2 + state, fast->known, (size_t)fast->known_size * sizeof(double));
    if (generated_step(arguments, fast->results) != 1)
        return 0;
    const double *results = fast->results;
    memcpy(fast->state, results, (size_t)state * sizeof(double));
    memcpy(fast->known, results + state, (size_t)inputs * sizeof(double));
    memcpy(fast->held, results + state, (size_t)inputs * sizeof(double));
    memcpy(fast->values, results + state + inputs, (size_t)fast->outputs * sizeof(double));
    return 1;
#else
    (void)fast, (void)time, (void)step;
    return 0;
#endif
}
