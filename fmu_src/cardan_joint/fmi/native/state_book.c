/* The FMU states an instance handed out and has not freed, for FMI 2.0 and 3.0:
 * pythonfmu takes a state pointer for a Python object, so a foreign, freed or
 * NULL one must never reach it (fmu_states.c, fmi3_states.c). */
#include "instance.h"

#include <stdlib.h>

static size_t find_state(const struct instance *in, fmi2FMUstate state)
{
    for (size_t i = 0; state && i < in->n_fmu_states; i++)
        if (in->fmu_states[i] == state)
            return i;
    return (size_t)-1;
}

int known_state(struct instance *in, fmi2FMUstate state, const char *function)
{
    if (find_state(in, state) != (size_t)-1)
        return 1;
    reportf(in, fmi2Error, "%s got FMU state %p, which this instance did not create or has "
            "already freed; the call was ignored", function, state);
    return 0;
}

void keep_state(struct instance *in, fmi2FMUstate state)
{
    if (in->n_fmu_states == in->fmu_states_capacity) {
        size_t capacity = in->fmu_states_capacity ? 2 * in->fmu_states_capacity : 8;
        fmi2FMUstate *grown = realloc(in->fmu_states, capacity * sizeof *grown);
        if (!grown)
            return;
        in->fmu_states = grown;
        in->fmu_states_capacity = capacity;
    }
    in->fmu_states[in->n_fmu_states++] = state;
}

fmi2Status drop_state(struct instance *in, fmi2FMUstate *state)
{
    size_t i = find_state(in, *state);
    if (i == (size_t)-1) /* callers check known_state first: never free a foreign state */
        return fmi2Error;
    in->fmu_states[i] = in->fmu_states[--in->n_fmu_states];
    return free_slave_state(in, state);
}

/* A new state goes into *state; one of ours already there is replaced. */
int prepare_new_state(struct instance *in, fmi2FMUstate *state, const char *function)
{
    if (!state) {
        reportf(in, fmi2Error, "%s got a NULL pointer for the FMU state", function);
        return 0;
    }
    if (*state) {
        if (!known_state(in, *state, function))
            return 0;
        drop_state(in, state);
        *state = NULL;
    }
    return 1;
}

