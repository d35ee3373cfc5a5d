/* The FMI 3.0 test host's view of one loaded FMU (see host3.c). */
#ifndef HOST3_H
#define HOST3_H

#include <stdio.h>
#include <stdlib.h>

#include "fmi3FunctionTypes.h"

#define FUNCTIONS(X)                                                                         \
    X(InstantiateCoSimulation) X(InstantiateModelExchange) X(FreeInstance)                   \
    X(EnterInitializationMode) X(ExitInitializationMode) X(Terminate) X(Reset)               \
    X(GetFloat64) X(SetFloat64) X(GetFloat32) X(GetClock) X(EnterEventMode)                  \
    X(UpdateDiscreteStates) X(GetDirectionalDerivative) X(DoStep) X(GetFMUState)              \
    X(SetFMUState) X(FreeFMUState) X(SerializedFMUStateSize) X(SerializeFMUState)            \
    X(DeserializeFMUState) X(GetInt32) X(SetDebugLogging)

struct fmu3 {
    char token[128], identifier[64], resources[4200];
    struct variable {
        char name[64], causality[16];
        fmi3ValueReference vr;
        int size;
    } variables[64];
    int n_variables;
#define MEMBER(name) fmi3##name##TYPE *name;
    FUNCTIONS(MEMBER)
#undef MEMBER
};

extern struct fmu3 fmu;
extern int log_calls;
extern char last_message[2048];

#define fail(...) (fprintf(stderr, "host3: " __VA_ARGS__), fputc('\n', stderr), exit(1))
#define check(status, what)                                                                \
    do {                                                                                   \
        fmi3Status check_ = (status);                                                      \
        if (check_ > fmi3Warning)                                                          \
            fail("%s returned %d: %s", what, check_, last_message);                       \
    } while (0)

void logger(fmi3InstanceEnvironment env, fmi3Status status, fmi3String category,
            fmi3String message);
void load(const char *dir);
const struct variable *variable(const char *name);
fmi3Instance instantiate(const char *name, fmi3Boolean logging_on);
fmi3Instance start(const char *name);
void initialize(fmi3Instance c);
fmi3Status step(fmi3Instance c, double time, double h);
void simulate(FILE *out, int steps, double dt, int n_settings, char **settings);
int threads3(int steps);
int fuzz3(unsigned seed, int count);
int refusal3(const char *name, double value);

#endif
