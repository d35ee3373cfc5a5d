/* The fmi2 functions on FMU states. An instance accepts only the states it
 * handed out and has not freed: a foreign, freed or NULL state pointer is
 * answered with fmi2Error and a message, without reaching Python. */
#include "instance.h"

#include <stdlib.h>

/* --- FMU states: only those this instance handed out and did not free ---------- */

static size_t find_state(const struct instance *in, fmi2FMUstate state)
{
    for (size_t i = 0; state && i < in->n_fmu_states; i++)
        if (in->fmu_states[i] == state)
            return i;
    return (size_t)-1;
}

static int known_state(struct instance *in, fmi2FMUstate state, const char *function)
{
    if (find_state(in, state) != (size_t)-1)
        return 1;
    reportf(in, fmi2Error, "%s got FMU state %p, which this instance did not create or has "
            "already freed; the call was ignored", function, state);
    return 0;
}

static void keep_state(struct instance *in, fmi2FMUstate state)
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
    in->fmu_states[i] = in->fmu_states[--in->n_fmu_states];
    return slave.free_fmu_state(in->slave, state);
}

/* A new state goes into *state; one of ours already there is replaced. */
static int prepare_new_state(struct instance *in, fmi2FMUstate *state, const char *function)
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

/* --- FMU state ---------------------------------------------------------------- */

fmi2Status fmi2GetFMUstate(fmi2Component c, fmi2FMUstate *state)
{
    struct instance *in = enter(c, ALIVE, "fmi2GetFMUstate");
    if (!in || !prepare_new_state(in, state, "fmi2GetFMUstate"))
        return fmi2Error;
    fmi2Status status = leave(in, slave.get_fmu_state(in->slave, state));
    if (*state)
        keep_state(in, *state);
    return status;
}

fmi2Status fmi2SetFMUstate(fmi2Component c, fmi2FMUstate state)
{
    struct instance *in = enter(c, ALIVE, "fmi2SetFMUstate");
    if (!in || !known_state(in, state, "fmi2SetFMUstate"))
        return fmi2Error;
    return leave(in, slave.set_fmu_state(in->slave, state));
}

fmi2Status fmi2FreeFMUstate(fmi2Component c, fmi2FMUstate *state)
{
    struct instance *in = enter(c, ANY, "fmi2FreeFMUstate");
    if (!in)
        return fmi2Error;
    if (!state || !*state)
        return fmi2OK;  /* the standard makes freeing NULL a no-op */
    if (!known_state(in, *state, "fmi2FreeFMUstate"))
        return fmi2Error;
    fmi2Status status = leave(in, drop_state(in, state));
    *state = NULL;
    return status;
}

fmi2Status fmi2SerializedFMUstateSize(fmi2Component c, fmi2FMUstate state, size_t *size)
{
    struct instance *in = enter(c, ALIVE, "fmi2SerializedFMUstateSize");
    if (!in || !known_state(in, state, "fmi2SerializedFMUstateSize") ||
        !arrays_given(in, "fmi2SerializedFMUstateSize", 1, size, size))
        return fmi2Error;
    return leave(in, slave.serialized_size(in->slave, state, size));
}

fmi2Status fmi2SerializeFMUstate(fmi2Component c, fmi2FMUstate state, fmi2Byte bytes[], size_t size)
{
    struct instance *in = enter(c, ALIVE, "fmi2SerializeFMUstate");
    size_t needed = 0;
    if (!in || !known_state(in, state, "fmi2SerializeFMUstate") ||
        !arrays_given(in, "fmi2SerializeFMUstate", size, bytes, bytes))
        return fmi2Error;
    if (slave.serialized_size(in->slave, state, &needed) != fmi2OK || size < needed) {
        reportf(in, fmi2Error, "fmi2SerializeFMUstate got %zu bytes for a state of %zu bytes; "
                "ask fmi2SerializedFMUstateSize first", size, needed);
        return fmi2Error;
    }
    /* pythonfmu copies as many bytes as it is told, from a state only `needed` long. */
    return leave(in, slave.serialize(in->slave, state, bytes, needed));
}

fmi2Status fmi2DeSerializeFMUstate(fmi2Component c, const fmi2Byte bytes[], size_t size,
                                   fmi2FMUstate *state)
{
    struct instance *in = enter(c, ALIVE, "fmi2DeSerializeFMUstate");
    if (!in || !arrays_given(in, "fmi2DeSerializeFMUstate", size, bytes, bytes) ||
        !prepare_new_state(in, state, "fmi2DeSerializeFMUstate"))
        return fmi2Error;
    fmi2Status status = leave(in, slave.deserialize(in->slave, bytes, size, state));
    if (*state)
        keep_state(in, *state);
    return status;
}

