/* The fmi3 functions on FMU states (state_book.c serves both FMI versions). */
#include "fmi3_instance.h"

fmi3Status fmi3GetFMUState(fmi3Instance c, fmi3FMUState *state)
{
    return (fmi3Status)state_get(c, state, CALL(fmi3GetFMUState));
}

fmi3Status fmi3SetFMUState(fmi3Instance c, fmi3FMUState state)
{
    return (fmi3Status)state_set(c, state, CALL(fmi3SetFMUState));
}

fmi3Status fmi3FreeFMUState(fmi3Instance c, fmi3FMUState *state)
{
    return (fmi3Status)state_free(c, state, CALL(fmi3FreeFMUState));
}

fmi3Status fmi3SerializedFMUStateSize(fmi3Instance c, fmi3FMUState state, size_t *size)
{
    return (fmi3Status)state_size(c, state, size, CALL(fmi3SerializedFMUStateSize));
}

fmi3Status fmi3SerializeFMUState(fmi3Instance c, fmi3FMUState state, fmi3Byte bytes[],
                                 size_t size)
{
    return (fmi3Status)state_serialize(c, state, (char *)bytes, size, CALL(fmi3SerializeFMUState));
}

fmi3Status fmi3DeserializeFMUState(fmi3Instance c, const fmi3Byte bytes[], size_t size,
                                   fmi3FMUState *state)
{
    return (fmi3Status)state_deserialize(c, (const char *)bytes, size, state,
                                         CALL(fmi3DeserializeFMUState));
}
