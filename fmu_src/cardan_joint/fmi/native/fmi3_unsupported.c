/* The fmi3 functions this FMU does not support: each answers fmi3Error with a
 * message saying why (pythonfmu3 would abort the host on most of them). */
#include "fmi3_instance.h"

fmi3Status unsupported3(fmi3Instance instance, unsigned allowed, const char *function,
                        const char *why)
{
    struct instance *in = enter(instance, allowed, function);
    if (in)
        reportf(in, fmi2Error, "%s is not supported: %s", function, why);
    return fmi3Error;
}

fmi3Status fmi3EnterEventMode(fmi3Instance instance)
{
    return unsupported3(instance, CALL(fmi3EnterEventMode),
                        "this FMU has no event mode (hasEventMode is false)");
}

fmi3Status fmi3EnterStepMode(fmi3Instance instance)
{
    return unsupported3(instance, CALL(fmi3EnterStepMode),
                        "this FMU has no event mode, so it never leaves step mode");
}

fmi3Status fmi3GetBinary(fmi3Instance instance, const fmi3ValueReference valueReferences[],
                         size_t nValueReferences, size_t valueSizes[], fmi3Binary values[],
                         size_t nValues)
{
    (void)valueReferences, (void)nValueReferences, (void)valueSizes, (void)values, (void)nValues;
    return unsupported3(instance, CALL(fmi3GetBinary), "the FMU has no Binary variables");
}

fmi3Status fmi3SetBinary(fmi3Instance instance, const fmi3ValueReference valueReferences[],
                         size_t nValueReferences, const size_t valueSizes[],
                         const fmi3Binary values[], size_t nValues)
{
    (void)valueReferences, (void)nValueReferences, (void)valueSizes, (void)values, (void)nValues;
    return unsupported3(instance, CALL(fmi3SetBinary), "the FMU has no Binary variables");
}

fmi3Status fmi3GetClock(fmi3Instance instance, const fmi3ValueReference valueReferences[],
                        size_t nValueReferences, fmi3Clock values[])
{
    (void)valueReferences, (void)nValueReferences, (void)values;
    return unsupported3(instance, CALL(fmi3GetClock), "the FMU has no clocks");
}

fmi3Status fmi3SetClock(fmi3Instance instance, const fmi3ValueReference valueReferences[],
                        size_t nValueReferences, const fmi3Clock values[])
{
    (void)valueReferences, (void)nValueReferences, (void)values;
    return unsupported3(instance, CALL(fmi3SetClock), "the FMU has no clocks");
}

fmi3Status fmi3GetNumberOfVariableDependencies(fmi3Instance instance,
                                               fmi3ValueReference valueReference,
                                               size_t* nDependencies)
{
    (void)valueReference, (void)nDependencies;
    return unsupported3(instance, CALL(fmi3GetNumberOfVariableDependencies),
                        "the dependencies are in modelDescription.xml");
}

fmi3Status fmi3GetVariableDependencies(fmi3Instance instance, fmi3ValueReference dependent,
                                       size_t elementIndicesOfDependent[],
                                       fmi3ValueReference independents[],
                                       size_t elementIndicesOfIndependents[],
                                       fmi3DependencyKind dependencyKinds[], size_t nDependencies)
{
    (void)dependent, (void)elementIndicesOfDependent, (void)independents, (void)elementIndicesOfIndependents, (void)dependencyKinds, (void)nDependencies;
    return unsupported3(instance, CALL(fmi3GetVariableDependencies),
                        "the dependencies are in modelDescription.xml");
}

fmi3Status fmi3GetDirectionalDerivative(fmi3Instance instance,
                                        const fmi3ValueReference unknowns[], size_t nUnknowns,
                                        const fmi3ValueReference knowns[], size_t nKnowns,
                                        const fmi3Float64 seed[], size_t nSeed,
                                        fmi3Float64 sensitivity[], size_t nSensitivity)
{
    (void)unknowns, (void)nUnknowns, (void)knowns, (void)nKnowns, (void)seed, (void)nSeed, (void)sensitivity, (void)nSensitivity;
    return unsupported3(instance, CALL(fmi3GetDirectionalDerivative),
                        "providesDirectionalDerivatives is false");
}

fmi3Status fmi3GetAdjointDerivative(fmi3Instance instance, const fmi3ValueReference unknowns[],
                                    size_t nUnknowns, const fmi3ValueReference knowns[],
                                    size_t nKnowns, const fmi3Float64 seed[], size_t nSeed,
                                    fmi3Float64 sensitivity[], size_t nSensitivity)
{
    (void)unknowns, (void)nUnknowns, (void)knowns, (void)nKnowns, (void)seed, (void)nSeed, (void)sensitivity, (void)nSensitivity;
    return unsupported3(instance, CALL(fmi3GetAdjointDerivative),
                        "providesAdjointDerivatives is false");
}

fmi3Status fmi3EnterConfigurationMode(fmi3Instance instance)
{
    return unsupported3(instance, CALL(fmi3EnterConfigurationMode),
                        "the FMU has no structural parameters");
}

fmi3Status fmi3ExitConfigurationMode(fmi3Instance instance)
{
    return unsupported3(instance, CALL(fmi3ExitConfigurationMode),
                        "the FMU has no structural parameters");
}

fmi3Status fmi3GetOutputDerivatives(fmi3Instance instance,
                                    const fmi3ValueReference valueReferences[],
                                    size_t nValueReferences, const fmi3Int32 orders[],
                                    fmi3Float64 values[], size_t nValues)
{
    (void)valueReferences, (void)nValueReferences, (void)orders, (void)values, (void)nValues;
    return unsupported3(instance, CALL(fmi3GetOutputDerivatives), "maxOutputDerivativeOrder is 0");
}

fmi3Status fmi3GetIntervalDecimal(fmi3Instance instance,
                                  const fmi3ValueReference valueReferences[],
                                  size_t nValueReferences, fmi3Float64 intervals[],
                                  fmi3IntervalQualifier qualifiers[])
{
    (void)valueReferences, (void)nValueReferences, (void)intervals, (void)qualifiers;
    return unsupported3(instance, CALL(fmi3GetIntervalDecimal),
                        "the FMU has no clocks (co-simulation without scheduled execution)");
}

fmi3Status fmi3GetIntervalFraction(fmi3Instance instance,
                                   const fmi3ValueReference valueReferences[],
                                   size_t nValueReferences, fmi3UInt64 counters[],
                                   fmi3UInt64 resolutions[], fmi3IntervalQualifier qualifiers[])
{
    (void)valueReferences, (void)nValueReferences, (void)counters, (void)resolutions, (void)qualifiers;
    return unsupported3(instance, CALL(fmi3GetIntervalFraction),
                        "the FMU has no clocks (co-simulation without scheduled execution)");
}

fmi3Status fmi3GetShiftDecimal(fmi3Instance instance, const fmi3ValueReference valueReferences[],
                               size_t nValueReferences, fmi3Float64 shifts[])
{
    (void)valueReferences, (void)nValueReferences, (void)shifts;
    return unsupported3(instance, CALL(fmi3GetShiftDecimal),
                        "the FMU has no clocks (co-simulation without scheduled execution)");
}

fmi3Status fmi3GetShiftFraction(fmi3Instance instance, const fmi3ValueReference valueReferences[],
                                size_t nValueReferences, fmi3UInt64 counters[],
                                fmi3UInt64 resolutions[])
{
    (void)valueReferences, (void)nValueReferences, (void)counters, (void)resolutions;
    return unsupported3(instance, CALL(fmi3GetShiftFraction),
                        "the FMU has no clocks (co-simulation without scheduled execution)");
}

fmi3Status fmi3SetIntervalDecimal(fmi3Instance instance,
                                  const fmi3ValueReference valueReferences[],
                                  size_t nValueReferences, const fmi3Float64 intervals[])
{
    (void)valueReferences, (void)nValueReferences, (void)intervals;
    return unsupported3(instance, CALL(fmi3SetIntervalDecimal),
                        "the FMU has no clocks (co-simulation without scheduled execution)");
}

fmi3Status fmi3SetIntervalFraction(fmi3Instance instance,
                                   const fmi3ValueReference valueReferences[],
                                   size_t nValueReferences, const fmi3UInt64 counters[],
                                   const fmi3UInt64 resolutions[])
{
    (void)valueReferences, (void)nValueReferences, (void)counters, (void)resolutions;
    return unsupported3(instance, CALL(fmi3SetIntervalFraction),
                        "the FMU has no clocks (co-simulation without scheduled execution)");
}

fmi3Status fmi3SetShiftDecimal(fmi3Instance instance, const fmi3ValueReference valueReferences[],
                               size_t nValueReferences, const fmi3Float64 shifts[])
{
    (void)valueReferences, (void)nValueReferences, (void)shifts;
    return unsupported3(instance, CALL(fmi3SetShiftDecimal),
                        "the FMU has no clocks (co-simulation without scheduled execution)");
}

fmi3Status fmi3SetShiftFraction(fmi3Instance instance, const fmi3ValueReference valueReferences[],
                                size_t nValueReferences, const fmi3UInt64 counters[],
                                const fmi3UInt64 resolutions[])
{
    (void)valueReferences, (void)nValueReferences, (void)counters, (void)resolutions;
    return unsupported3(instance, CALL(fmi3SetShiftFraction),
                        "the FMU has no clocks (co-simulation without scheduled execution)");
}

fmi3Status fmi3ActivateModelPartition(fmi3Instance instance, fmi3ValueReference clockReference,
                                      fmi3Float64 activationTime)
{
    (void)clockReference, (void)activationTime;
    return unsupported3(instance, CALL(fmi3ActivateModelPartition),
                        "the FMU has no clocks (co- simulation without scheduled execution)");
}

fmi3Status fmi3EvaluateDiscreteStates(fmi3Instance instance)
{
    return unsupported3(instance, CALL(fmi3EvaluateDiscreteStates),
                        "the FMU has no clocks (co- simulation without scheduled execution)");
}

fmi3Status fmi3UpdateDiscreteStates(fmi3Instance instance, fmi3Boolean* discreteStatesNeedUpdate,
                                    fmi3Boolean* terminateSimulation,
                                    fmi3Boolean* nominalsOfContinuousStatesChanged,
                                    fmi3Boolean* valuesOfContinuousStatesChanged,
                                    fmi3Boolean* nextEventTimeDefined, fmi3Float64* nextEventTime)
{
    (void)discreteStatesNeedUpdate, (void)terminateSimulation, (void)nominalsOfContinuousStatesChanged, (void)valuesOfContinuousStatesChanged, (void)nextEventTimeDefined, (void)nextEventTime;
    return unsupported3(instance, CALL(fmi3UpdateDiscreteStates),
                        "this FMU is for co-simulation only (no model exchange)");
}

fmi3Status fmi3EnterContinuousTimeMode(fmi3Instance instance)
{
    return unsupported3(instance, CALL(fmi3EnterContinuousTimeMode),
                        "this FMU is for co-simulation only (no model exchange)");
}

fmi3Status fmi3CompletedIntegratorStep(fmi3Instance instance,
                                       fmi3Boolean noSetFMUStatePriorToCurrentPoint,
                                       fmi3Boolean* enterEventMode,
                                       fmi3Boolean* terminateSimulation)
{
    (void)noSetFMUStatePriorToCurrentPoint, (void)enterEventMode, (void)terminateSimulation;
    return unsupported3(instance, CALL(fmi3CompletedIntegratorStep),
                        "this FMU is for co-simulation only (no model exchange)");
}

fmi3Status fmi3SetTime(fmi3Instance instance, fmi3Float64 time)
{
    (void)time;
    return unsupported3(instance, CALL(fmi3SetTime),
                        "this FMU is for co-simulation only (no model exchange)");
}

fmi3Status fmi3SetContinuousStates(fmi3Instance instance, const fmi3Float64 continuousStates[],
                                   size_t nContinuousStates)
{
    (void)continuousStates, (void)nContinuousStates;
    return unsupported3(instance, CALL(fmi3SetContinuousStates),
                        "this FMU is for co-simulation only (no model exchange)");
}

fmi3Status fmi3GetContinuousStateDerivatives(fmi3Instance instance, fmi3Float64 derivatives[],
                                             size_t nContinuousStates)
{
    (void)derivatives, (void)nContinuousStates;
    return unsupported3(instance, CALL(fmi3GetContinuousStateDerivatives),
                        "this FMU is for co- simulation only (no model exchange)");
}

fmi3Status fmi3GetEventIndicators(fmi3Instance instance, fmi3Float64 eventIndicators[],
                                  size_t nEventIndicators)
{
    (void)eventIndicators, (void)nEventIndicators;
    return unsupported3(instance, CALL(fmi3GetEventIndicators),
                        "this FMU is for co-simulation only (no model exchange)");
}

fmi3Status fmi3GetContinuousStates(fmi3Instance instance, fmi3Float64 continuousStates[],
                                   size_t nContinuousStates)
{
    (void)continuousStates, (void)nContinuousStates;
    return unsupported3(instance, CALL(fmi3GetContinuousStates),
                        "this FMU is for co-simulation only (no model exchange)");
}

fmi3Status fmi3GetNominalsOfContinuousStates(fmi3Instance instance, fmi3Float64 nominals[],
                                             size_t nContinuousStates)
{
    (void)nominals, (void)nContinuousStates;
    return unsupported3(instance, CALL(fmi3GetNominalsOfContinuousStates),
                        "this FMU is for co- simulation only (no model exchange)");
}

fmi3Status fmi3GetNumberOfEventIndicators(fmi3Instance instance, size_t* nEventIndicators)
{
    (void)nEventIndicators;
    return unsupported3(instance, CALL(fmi3GetNumberOfEventIndicators),
                        "this FMU is for co-simulation only (no model exchange)");
}

fmi3Status fmi3GetNumberOfContinuousStates(fmi3Instance instance, size_t* nContinuousStates)
{
    (void)nContinuousStates;
    return unsupported3(instance, CALL(fmi3GetNumberOfContinuousStates),
                        "this FMU is for co- simulation only (no model exchange)");
}
