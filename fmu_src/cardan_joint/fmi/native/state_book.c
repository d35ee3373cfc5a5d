/* The FMU state calls of FMI 2.0 and 3.0 (fmu_states.c, fmi3_states.c name
 * them) and the states an instance handed out and has not freed: the runtime
 * takes a state pointer for the slave's Python object, so a foreign, freed or
 * NULL one is answered with Error and a message, without reaching Python. */
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
            "already freed; the call was ignored", function, (void *)state);
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
    return slave_free_state(state);
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

/* --- the calls, for both FMI versions ---------------------------------------- */

fmi2Status state_get(void *c, fmi2FMUstate *state, unsigned allowed, const char *function)
{
    struct instance *in = enter(c, allowed, function);
    if (!in || !prepare_new_state(in, state, function))
        return fmi2Error;
    if (fast_before(in))
        return leave(in, fmi2Error);
    fmi2Status status = leave(in, slave_get_state(in, state));
    if (*state)
        keep_state(in, *state);
    return status;
}

fmi2Status state_set(void *c, fmi2FMUstate state, unsigned allowed, const char *function)
{
    struct instance *in = enter(c, allowed, function);
    if (!in || !known_state(in, state, function))
        return fmi2Error;
    if (fast_before(in))
        return leave(in, fmi2Error);
    int refused = 0;
    fmi2Status status = leave(in, slave_set_state(in, state, &refused));
    if (!refused) /* a refused state leaves the instance as it was: the arrays hold */
        fast_after(in);
    restore_mode(in, status);
    return status;
}

fmi2Status state_free(void *c, fmi2FMUstate *state, unsigned allowed, const char *function)
{
    struct instance *in = enter(c, allowed, function);
    if (!in)
        return fmi2Error;
    /* Before *state is read: a host that passes the state where its address
     * belongs (fmusim 0.0.39's Free*FMUState(S, FMUState)) hands us our own
     * Python object, whose first word is no state. */
    if (find_state(in, (fmi2FMUstate)state) != (size_t)-1) {
        reportf(in, fmi2Error, "%s got the FMU state %p itself where the address of the "
                "host's state variable belongs (state passed, not &state, as fmusim 0.0.39 "
                "does); the state was not freed", function, (void *)state);
        return fmi2Error;
    }
    if (!state || !*state)
        return fmi2OK;  /* the standard makes freeing NULL a no-op */
    if (!known_state(in, *state, function))
        return fmi2Error;
    fmi2Status status = leave(in, drop_state(in, state));
    *state = NULL;
    return status;
}

fmi2Status state_size(void *c, fmi2FMUstate state, size_t *size,
                      unsigned allowed, const char *function)
{
    struct instance *in = enter(c, allowed, function);
    if (!in || !known_state(in, state, function) ||
        !arrays_given(in, function, 1, size, size))
        return fmi2Error;
    return leave(in, slave_state_bytes(in, state, NULL, size));
}

fmi2Status state_serialize(void *c, fmi2FMUstate state, char bytes[], size_t size,
                           unsigned allowed, const char *function)
{
    struct instance *in = enter(c, allowed, function);
    size_t needed = 0;
    if (!in || !known_state(in, state, function) ||
        !arrays_given(in, function, size, bytes, bytes))
        return fmi2Error;
    if (slave_state_bytes(in, state, NULL, &needed) != fmi2OK || size < needed) {
        /* fmi<v>SerializeFMU<s>tate's size function: fmi<v>SerializedFMU<s>tateSize */
        reportf(in, fmi2Error, "%s got %zu bytes for a state of %zu bytes; ask %.13sd%sSize "
                "first", function, size, needed, function, function + 13);
        return fmi2Error;
    }
    return leave(in, slave_state_bytes(in, state, bytes, &needed));
}

fmi2Status state_deserialize(void *c, const char bytes[], size_t size, fmi2FMUstate *state,
                             unsigned allowed, const char *function)
{
    struct instance *in = enter(c, allowed, function);
    if (!in || !arrays_given(in, function, size, bytes, bytes) ||
        !prepare_new_state(in, state, function))
        return fmi2Error;
    fmi2Status status = leave(in, slave_state_from_bytes(in, bytes, size, state));
    if (*state)
        keep_state(in, *state);
    return status;
}
