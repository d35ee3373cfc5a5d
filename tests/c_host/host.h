/* The test host's view of one loaded FMU (see host.c). */
#ifndef HOST_H
#define HOST_H

#include <stdio.h>
#include <stdlib.h>

#include "fmi2.h"

#define FMI_FUNCTIONS(X)                                                                  \
    X(Instantiate) X(FreeInstance) X(SetupExperiment) X(EnterInitializationMode)          \
    X(ExitInitializationMode) X(Terminate) X(Reset) X(GetReal) X(SetReal) X(GetInteger)   \
    X(GetBoolean) X(GetString) X(DoStep) X(CancelStep) X(GetStatus) X(GetFMUstate)        \
    X(SetFMUstate) X(FreeFMUstate) X(SerializedFMUstateSize) X(SerializeFMUstate)         \
    X(DeSerializeFMUstate) X(SetDebugLogging) X(GetBooleanStatus)

/* Prototypes of the FMI functions, for the types above only. */
fmi2Component fmi2Instantiate(fmi2String, fmi2Type, fmi2String, fmi2String,
                              const fmi2CallbackFunctions *, fmi2Boolean, fmi2Boolean);
void fmi2FreeInstance(fmi2Component);
fmi2Status fmi2SetupExperiment(fmi2Component, fmi2Boolean, fmi2Real, fmi2Real, fmi2Boolean, fmi2Real);
fmi2Status fmi2EnterInitializationMode(fmi2Component);
fmi2Status fmi2ExitInitializationMode(fmi2Component);
fmi2Status fmi2Terminate(fmi2Component);
fmi2Status fmi2Reset(fmi2Component);
fmi2Status fmi2GetReal(fmi2Component, const fmi2ValueReference[], size_t, fmi2Real[]);
fmi2Status fmi2SetReal(fmi2Component, const fmi2ValueReference[], size_t, const fmi2Real[]);
fmi2Status fmi2GetInteger(fmi2Component, const fmi2ValueReference[], size_t, fmi2Integer[]);
fmi2Status fmi2GetBoolean(fmi2Component, const fmi2ValueReference[], size_t, fmi2Boolean[]);
fmi2Status fmi2GetString(fmi2Component, const fmi2ValueReference[], size_t, fmi2String[]);
fmi2Status fmi2DoStep(fmi2Component, fmi2Real, fmi2Real, fmi2Boolean);
fmi2Status fmi2CancelStep(fmi2Component);
fmi2Status fmi2GetStatus(fmi2Component, const fmi2StatusKind, fmi2Status *);
fmi2Status fmi2GetFMUstate(fmi2Component, fmi2FMUstate *);
fmi2Status fmi2SetFMUstate(fmi2Component, fmi2FMUstate);
fmi2Status fmi2FreeFMUstate(fmi2Component, fmi2FMUstate *);
fmi2Status fmi2SerializedFMUstateSize(fmi2Component, fmi2FMUstate, size_t *);
fmi2Status fmi2SerializeFMUstate(fmi2Component, fmi2FMUstate, fmi2Byte[], size_t);
fmi2Status fmi2DeSerializeFMUstate(fmi2Component, const fmi2Byte[], size_t, fmi2FMUstate *);
fmi2Status fmi2SetDebugLogging(fmi2Component, fmi2Boolean, size_t, const fmi2String[]);
fmi2Status fmi2GetBooleanStatus(fmi2Component, const fmi2StatusKind, fmi2Boolean *);

struct variable {
    char name[64], causality[16];
    fmi2ValueReference vr;
};

struct fmu {
    char guid[128], identifier[64], resources[4200];
    struct variable variables[64];
    int n_variables;
#define MEMBER(name) __typeof__(&fmi2##name) name;
    FMI_FUNCTIONS(MEMBER)
#undef MEMBER
};

extern struct fmu fmu;
extern int log_calls;
extern char last_message[2048];
extern const fmi2CallbackFunctions callbacks;

#define fail(...) (fprintf(stderr, "host: " __VA_ARGS__), fputc('\n', stderr), exit(1))
#define check(status, what)                                                            \
    do {                                                                               \
        fmi2Status check_ = (status);                                                  \
        if (check_ > fmi2Warning)                                                      \
            fail("%s returned %d: %s", what, check_, last_message);                   \
    } while (0)

void load(const char *dir);
fmi2ValueReference reference(const char *name);
int outputs(fmi2ValueReference *vr);
fmi2Component start(const char *name, fmi2Boolean logging_on);
void initialize(fmi2Component c);
int threads(const char *dir, int steps);
int fuzz(const char *dir, unsigned seed, int count);
int refusal(const char *dir, const char *name, double value);

#endif
