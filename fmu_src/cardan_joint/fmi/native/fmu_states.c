/* The fmi2 functions on FMU states (state_book.c serves both FMI versions). */
#include "instance.h"

fmi2Status fmi2GetFMUstate(fmi2Component c, fmi2FMUstate *state)
{
    return state_get(c, state, CALL(fmi2GetFMUstate));
}

fmi2Status fmi2SetFMUstate(fmi2Component c, fmi2FMUstate state)
{
    return state_set(c, state, CALL(fmi2SetFMUstate));
}

fmi2Status fmi2FreeFMUstate(fmi2Component c, fmi2FMUstate *state)
{
    return state_free(c, state, CALL(fmi2FreeFMUstate));
}

fmi2Status fmi2SerializedFMUstateSize(fmi2Component c, fmi2FMUstate state, size_t *size)
{
    return state_size(c, state, size, CALL(fmi2SerializedFMUstateSize));
}

fmi2Status fmi2SerializeFMUstate(fmi2Component c, fmi2FMUstate state, fmi2Byte bytes[],
                                 size_t size)
{
    return state_serialize(c, state, bytes, size, CALL(fmi2SerializeFMUstate));
}

fmi2Status fmi2DeSerializeFMUstate(fmi2Component c, const fmi2Byte bytes[], size_t size,
                                   fmi2FMUstate *state)
{
    return state_deserialize(c, bytes, size, state, CALL(fmi2DeSerializeFMUstate));
}
