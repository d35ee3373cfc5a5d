/* Which call is allowed in which state: one table per FMI version, as
 * Reference-FMUs' MASK_fmi2X / MASK_fmi3X.  Every call on an instance begins
 * with ENTER(c, F) (or passes CALL(F) to a helper that does): enter() checks
 * the instance and that its state is in MASK_F, names F in its message when
 * not (answered with Error, nothing changed), and leave() ends the call with
 * the worst status logged during it (calls.c).  Functions this FMU does not
 * support are allowed everywhere: they answer with Error and say why. */
#ifndef CARDAN_JOINT_MASKS_H
#define CARDAN_JOINT_MASKS_H

#define ALIVE (STATE_INSTANTIATED | STATE_INITIALIZATION | STATE_STEP_COMPLETE | STATE_TERMINATED)
#define ANY (ALIVE | STATE_FATAL | STATE_ERROR)
/* Reading before initialization is beyond FMI 2.0 but harmless: start values. */
#define READABLE ALIVE
#define SETTABLE (STATE_INSTANTIATED | STATE_INITIALIZATION | STATE_STEP_COMPLETE)

/* The mask and the name of FMI function F. */
#define CALL(F) MASK_##F, #F
#define ENTER(c, F) enter(c, CALL(F))

/* --- FMI 2.0 co-simulation ---------------------------------------------------- */
#define MASK_fmi2FreeInstance                     ANY
#define MASK_fmi2SetDebugLogging                  ANY
#define MASK_fmi2SetupExperiment                  STATE_INSTANTIATED
#define MASK_fmi2EnterInitializationMode          STATE_INSTANTIATED
#define MASK_fmi2ExitInitializationMode           STATE_INITIALIZATION
#define MASK_fmi2Terminate                        STATE_STEP_COMPLETE
#define MASK_fmi2Reset                            (ALIVE | STATE_ERROR)
#define MASK_fmi2DoStep                           STATE_STEP_COMPLETE
#define MASK_fmi2GetReal                          READABLE
#define MASK_fmi2GetInteger                       READABLE
#define MASK_fmi2GetBoolean                       READABLE
#define MASK_fmi2GetString                        READABLE
#define MASK_fmi2SetReal                          SETTABLE
#define MASK_fmi2SetInteger                       SETTABLE
#define MASK_fmi2SetBoolean                       SETTABLE
#define MASK_fmi2SetString                        SETTABLE
#define MASK_fmi2GetRealStatus                    READABLE
#define MASK_fmi2GetBooleanStatus                 READABLE
#define MASK_fmi2GetFMUstate                      ALIVE
#define MASK_fmi2SetFMUstate                      ALIVE
#define MASK_fmi2FreeFMUstate                     ANY
#define MASK_fmi2SerializedFMUstateSize           ALIVE
#define MASK_fmi2SerializeFMUstate                ALIVE
#define MASK_fmi2DeSerializeFMUstate              ALIVE
#define MASK_fmi2GetStatus                        ANY
#define MASK_fmi2GetIntegerStatus                 ANY
#define MASK_fmi2GetStringStatus                  ANY
#define MASK_fmi2CancelStep                       ANY
#define MASK_fmi2GetDirectionalDerivative         ANY
#define MASK_fmi2SetRealInputDerivatives          ANY
#define MASK_fmi2GetRealOutputDerivatives         ANY

/* --- FMI 3.0 co-simulation (no event mode, no configuration mode) -------------- */
#define MASK_fmi3FreeInstance                     ANY
#define MASK_fmi3SetDebugLogging                  ANY
#define MASK_fmi3EnterInitializationMode          STATE_INSTANTIATED
#define MASK_fmi3ExitInitializationMode           STATE_INITIALIZATION
#define MASK_fmi3Terminate                        STATE_STEP_COMPLETE
#define MASK_fmi3Reset                            (ALIVE | STATE_ERROR)
#define MASK_fmi3DoStep                           STATE_STEP_COMPLETE
#define MASK_fmi3GetFloat32                       READABLE
#define MASK_fmi3GetFloat64                       READABLE
#define MASK_fmi3GetInt8                          READABLE
#define MASK_fmi3GetUInt8                         READABLE
#define MASK_fmi3GetInt16                         READABLE
#define MASK_fmi3GetUInt16                        READABLE
#define MASK_fmi3GetInt32                         READABLE
#define MASK_fmi3GetUInt32                        READABLE
#define MASK_fmi3GetInt64                         READABLE
#define MASK_fmi3GetUInt64                        READABLE
#define MASK_fmi3GetBoolean                       READABLE
#define MASK_fmi3GetString                        READABLE
#define MASK_fmi3SetFloat32                       SETTABLE
#define MASK_fmi3SetFloat64                       SETTABLE
#define MASK_fmi3SetInt8                          SETTABLE
#define MASK_fmi3SetUInt8                         SETTABLE
#define MASK_fmi3SetInt16                         SETTABLE
#define MASK_fmi3SetUInt16                        SETTABLE
#define MASK_fmi3SetInt32                         SETTABLE
#define MASK_fmi3SetUInt32                        SETTABLE
#define MASK_fmi3SetInt64                         SETTABLE
#define MASK_fmi3SetUInt64                        SETTABLE
#define MASK_fmi3SetBoolean                       SETTABLE
#define MASK_fmi3SetString                        SETTABLE
#define MASK_fmi3GetFMUState                      ALIVE
#define MASK_fmi3SetFMUState                      ALIVE
#define MASK_fmi3FreeFMUState                     ANY
#define MASK_fmi3SerializedFMUStateSize           ALIVE
#define MASK_fmi3SerializeFMUState                ALIVE
#define MASK_fmi3DeserializeFMUState              ALIVE
#define MASK_fmi3EnterEventMode                   ANY
#define MASK_fmi3EnterStepMode                    ANY
#define MASK_fmi3GetBinary                        ANY
#define MASK_fmi3SetBinary                        ANY
#define MASK_fmi3GetClock                         ANY
#define MASK_fmi3SetClock                         ANY
#define MASK_fmi3GetNumberOfVariableDependencies  ANY
#define MASK_fmi3GetVariableDependencies          ANY
#define MASK_fmi3GetDirectionalDerivative         ANY
#define MASK_fmi3GetAdjointDerivative             ANY
#define MASK_fmi3EnterConfigurationMode           ANY
#define MASK_fmi3ExitConfigurationMode            ANY
#define MASK_fmi3GetOutputDerivatives             ANY
#define MASK_fmi3GetIntervalDecimal               ANY
#define MASK_fmi3GetIntervalFraction              ANY
#define MASK_fmi3GetShiftDecimal                  ANY
#define MASK_fmi3GetShiftFraction                 ANY
#define MASK_fmi3SetIntervalDecimal               ANY
#define MASK_fmi3SetIntervalFraction              ANY
#define MASK_fmi3SetShiftDecimal                  ANY
#define MASK_fmi3SetShiftFraction                 ANY
#define MASK_fmi3ActivateModelPartition           ANY
#define MASK_fmi3EvaluateDiscreteStates           ANY
#define MASK_fmi3UpdateDiscreteStates             ANY
#define MASK_fmi3EnterContinuousTimeMode          ANY
#define MASK_fmi3CompletedIntegratorStep          ANY
#define MASK_fmi3SetTime                          ANY
#define MASK_fmi3SetContinuousStates              ANY
#define MASK_fmi3GetContinuousStateDerivatives    ANY
#define MASK_fmi3GetEventIndicators               ANY
#define MASK_fmi3GetContinuousStates              ANY
#define MASK_fmi3GetNominalsOfContinuousStates    ANY
#define MASK_fmi3GetNumberOfEventIndicators       ANY
#define MASK_fmi3GetNumberOfContinuousStates      ANY

#endif
