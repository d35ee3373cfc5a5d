/* The fmi3 functions on FMU states, as fmu_states.c for FMI 2.0: an instance
 * accepts only the states it handed out and has not freed (state_book.c); a
 * foreign, freed or NULL state pointer is answered with fmi3Error and a
 * message, without reaching Python. */
#include "fmi3_instance.h"

/* pythonfmu3's free, for drop_state (state_book.c). */
fmi2Status free_slave_state(struct instance *in, fmi2FMUstate *state)
{
    return (fmi2Status)slave3.free_fmu_state(in->slave, state);
}

fmi3Status fmi3GetFMUState(fmi3Instance c, fmi3FMUState *state)
{
    struct instance *in = enter(c, ALIVE, "fmi3GetFMUState");
    if (!in || !prepare_new_state(in, state, "fmi3GetFMUState"))
        return fmi3Error;
    fast_before(in);
    fmi2Status status = leave(in, (fmi2Status)slave3.get_fmu_state(in->slave, state));
    if (*state)
        keep_state(in, *state);
    return (fmi3Status)status;
}

fmi3Status fmi3SetFMUState(fmi3Instance c, fmi3FMUState state)
{
    struct instance *in = enter(c, ALIVE, "fmi3SetFMUState");
    if (!in || !known_state(in, state, "fmi3SetFMUState"))
        return fmi3Error;
    fast_before(in);
    fmi2Status status = leave(in, (fmi2Status)slave3.set_fmu_state(in->slave, state));
    fast_after(in);
    restore_mode(in, status);
    return (fmi3Status)status;
}

fmi3Status fmi3FreeFMUState(fmi3Instance c, fmi3FMUState *state)
{
    struct instance *in = enter(c, ANY, "fmi3FreeFMUState");
    if (!in)
        return fmi3Error;
    if (!state || !*state)
        return fmi3OK;  /* the standard makes freeing NULL a no-op */
    if (!known_state(in, *state, "fmi3FreeFMUState"))
        return fmi3Error;
    fmi2Status status = leave(in, drop_state(in, state));
    *state = NULL;
    return (fmi3Status)status;
}

fmi3Status fmi3SerializedFMUStateSize(fmi3Instance c, fmi3FMUState state, size_t *size)
{
    struct instance *in = enter(c, ALIVE, "fmi3SerializedFMUStateSize");
    if (!in || !known_state(in, state, "fmi3SerializedFMUStateSize") ||
        !arrays_given(in, "fmi3SerializedFMUStateSize", 1, size, size))
        return fmi3Error;
    return (fmi3Status)leave(in, (fmi2Status)slave3.serialized_size(in->slave, state, size));
}

fmi3Status fmi3SerializeFMUState(fmi3Instance c, fmi3FMUState state, fmi3Byte bytes[],
                                 size_t size)
{
    struct instance *in = enter(c, ALIVE, "fmi3SerializeFMUState");
    size_t needed = 0;
    if (!in || !known_state(in, state, "fmi3SerializeFMUState") ||
        !arrays_given(in, "fmi3SerializeFMUState", size, bytes, bytes))
        return fmi3Error;
    if (slave3.serialized_size(in->slave, state, &needed) != fmi3OK || size < needed) {
        reportf(in, fmi2Error, "fmi3SerializeFMUState got %zu bytes for a state of %zu bytes; "
                "ask fmi3SerializedFMUStateSize first", size, needed);
        return fmi3Error;
    }
    /* pythonfmu3 copies as many bytes as it is told, from a state only `needed` long. */
    return (fmi3Status)leave(in, (fmi2Status)slave3.serialize(in->slave, state, bytes, needed));
}

fmi3Status fmi3DeserializeFMUState(fmi3Instance c, const fmi3Byte bytes[], size_t size,
                                   fmi3FMUState *state)
{
    struct instance *in = enter(c, ALIVE, "fmi3DeserializeFMUState");
    if (!in || !arrays_given(in, "fmi3DeserializeFMUState", size, bytes, bytes) ||
        !prepare_new_state(in, state, "fmi3DeserializeFMUState"))
        return fmi3Error;
    fmi2Status status = leave(in, (fmi2Status)slave3.deserialize(in->slave, bytes, size, state));
    if (*state)
        keep_state(in, *state);
    return (fmi3Status)status;
}
