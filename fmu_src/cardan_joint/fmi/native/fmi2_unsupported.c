/* The fmi2 functions this FMU does not support (its modelDescription says so):
 * each is answered with fmi2Error and a message saying why, without reaching
 * Python. */
#include "instance.h"

static fmi2Status unsupported(fmi2Component c, unsigned allowed, const char *function,
                              const char *why)
{
    struct instance *in = enter(c, allowed, function);
    if (in)
        reportf(in, fmi2Error, "%s is not supported: %s", function, why);
    return fmi2Error;
}

fmi2Status fmi2GetStatus(fmi2Component c, const fmi2StatusKind kind, fmi2Status *value)
{
    (void)kind, (void)value;
    return unsupported(c, CALL(fmi2GetStatus), "fmi2DoStep never returns fmi2Pending");
}

fmi2Status fmi2GetIntegerStatus(fmi2Component c, const fmi2StatusKind kind, fmi2Integer *value)
{
    (void)kind, (void)value;
    return unsupported(c, CALL(fmi2GetIntegerStatus), "the FMU has no integer status");
}

fmi2Status fmi2GetStringStatus(fmi2Component c, const fmi2StatusKind kind, fmi2String *value)
{
    (void)kind, (void)value;
    return unsupported(c, CALL(fmi2GetStringStatus), "fmi2DoStep never returns fmi2Pending");
}

fmi2Status fmi2CancelStep(fmi2Component c)
{
    return unsupported(c, CALL(fmi2CancelStep), "fmi2DoStep always completes before it returns");
}

fmi2Status fmi2GetDirectionalDerivative(fmi2Component c, const fmi2ValueReference u[], size_t nu,
                                        const fmi2ValueReference z[], size_t nz,
                                        const fmi2Real du[], fmi2Real dz[])
{
    (void)u, (void)nu, (void)z, (void)nz, (void)du, (void)dz;
    return unsupported(c, CALL(fmi2GetDirectionalDerivative),
                       "providesDirectionalDerivative is false");
}

fmi2Status fmi2SetRealInputDerivatives(fmi2Component c, const fmi2ValueReference vr[], size_t n,
                                       const fmi2Integer order[], const fmi2Real value[])
{
    (void)vr, (void)n, (void)order, (void)value;
    return unsupported(c, CALL(fmi2SetRealInputDerivatives),
                       "canInterpolateInputs is false: set the inputs at each step instead");
}

fmi2Status fmi2GetRealOutputDerivatives(fmi2Component c, const fmi2ValueReference vr[], size_t n,
                                        const fmi2Integer order[], fmi2Real value[])
{
    (void)vr, (void)n, (void)order, (void)value;
    return unsupported(c, CALL(fmi2GetRealOutputDerivatives), "maxOutputDerivativeOrder is 0");
}
