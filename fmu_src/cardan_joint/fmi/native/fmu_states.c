/* The fmi2 functions on FMU states. An instance accepts only the states it
 * handed out and has not freed: a foreign, freed or NULL state pointer is
 * answered with fmi2Error and a message, without reaching Python. */
#include "instance.h"

/* The slave's state object released, for drop_state (state_book.c). */
fmi2Status free_slave_state(struct instance *in, fmi2FMUstate *state)
{
    (void)in;
    return slave_free_state(state);
}

/* --- FMU state ---------------------------------------------------------------- */

fmi2Status fmi2GetFMUstate(fmi2Component c, fmi2FMUstate *state)
{
    struct instance *in = enter(c, ALIVE, "fmi2GetFMUstate");
    if (!in || !prepare_new_state(in, state, "fmi2GetFMUstate"))
        return fmi2Error;
    fast_before(in);
    fmi2Status status = leave(in, slave_get_state(in, state));
    if (*state)
        keep_state(in, *state);
    return status;
}

fmi2Status fmi2SetFMUstate(fmi2Component c, fmi2FMUstate state)
{
    struct instance *in = enter(c, ALIVE, "fmi2SetFMUstate");
    if (!in || !known_state(in, state, "fmi2SetFMUstate"))
        return fmi2Error;
    fast_before(in);
    fmi2Status status = leave(in, slave_set_state(in, state));
    fast_after(in);
    restore_mode(in, status);
    return status;
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
    return leave(in, slave_state_bytes(in, state, NULL, size));
}

fmi2Status fmi2SerializeFMUstate(fmi2Component c, fmi2FMUstate state, fmi2Byte bytes[], size_t size)
{
    struct instance *in = enter(c, ALIVE, "fmi2SerializeFMUstate");
    size_t needed = 0;
    if (!in || !known_state(in, state, "fmi2SerializeFMUstate") ||
        !arrays_given(in, "fmi2SerializeFMUstate", size, bytes, bytes))
        return fmi2Error;
    if (slave_state_bytes(in, state, NULL, &needed) != fmi2OK || size < needed) {
        reportf(in, fmi2Error, "fmi2SerializeFMUstate got %zu bytes for a state of %zu bytes; "
                "ask fmi2SerializedFMUstateSize first", size, needed);
        return fmi2Error;
    }
    return leave(in, slave_state_bytes(in, state, bytes, &needed));
}

fmi2Status fmi2DeSerializeFMUstate(fmi2Component c, const fmi2Byte bytes[], size_t size,
                                   fmi2FMUstate *state)
{
    struct instance *in = enter(c, ALIVE, "fmi2DeSerializeFMUstate");
    if (!in || !arrays_given(in, "fmi2DeSerializeFMUstate", size, bytes, bytes) ||
        !prepare_new_state(in, state, "fmi2DeSerializeFMUstate"))
        return fmi2Error;
    fmi2Status status = leave(in, slave_state_from_bytes(in, bytes, size, state));
    if (*state)
        keep_state(in, *state);
    return status;
}

