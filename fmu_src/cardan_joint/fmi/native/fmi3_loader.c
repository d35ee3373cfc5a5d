/* The FMI 3.0 FMU's binaries/x86_64-linux/<modelIdentifier>.so, its only
 * binary: the runtime of the FMI 2.0 FMU (loader.c) for FMI 3.0, which needs no
 * pythonfmu3 binary.  At instantiate it finds or starts the Python, imports the
 * slave's script module and constructs the slave (slave_object.c); every call
 * passes the co-simulation state machine (calls.c, fmi3_calls.c,
 * fmi3_states.c) and every message the slave logs goes to report() (report.c).
 * Every fmi3 function is defined here, in fmi3_calls.c, fmi3_states.c or
 * fmi3_unsupported.c. */
#define _GNU_SOURCE
#include "fmi3_instance.h"

#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

const char SLAVE_BASE[] = "Fmi3SlaveBase";

/* FMI 3.0 loggers take the message as it is (no printf format). */
int to_host(const struct instance *in, fmi2Status status, const char *category, const char *text)
{
    const struct instance3 *in3 = (const struct instance3 *)in;
    if (!in3->log_message)
        return 0;
    in3->log_message(in3->environment, (fmi3Status)status, category, text);
    return 1;
}

const char *where(enum state state)
{
    switch (state) {
    case STATE_INSTANTIATED:
        return "before initialization: call fmi3EnterInitializationMode and "
               "fmi3ExitInitializationMode first";
    case STATE_INITIALIZATION:
        return "in initialization mode: call fmi3ExitInitializationMode first";
    case STATE_STEP_COMPLETE:
        return "in step mode";
    case STATE_TERMINATED:
        return "after fmi3Terminate: call fmi3Reset to start again";
    case STATE_ERROR:
        return "after an error that left the slave out of step with the instance: call "
               "fmi3Reset to start again, or fmi3FreeInstance";
    default:
        return "after a fatal error: only fmi3FreeInstance is allowed";
    }
}

static void early_message(const char *name, fmi3InstanceEnvironment environment,
                          fmi3LogMessageCallback log_message, const char *text)
{
    struct instance3 scratch = {.base = {.name = (char *)(name ? name : "?"),
                                         .model = MODEL_IDENTIFIER},
                                .environment = environment,
                                .log_message = log_message};
    scratch.base.shared_proxy = is_shared_proxy((void *)log_message);
    report(&scratch.base, fmi2Error, NULL, text);
}

/* The variables are the same for every instance of this FMU: read once. */
static const struct variables *variables_of(const char *resources, char *error, size_t size)
{
    static struct variables variables;
    static pthread_mutex_t lock = PTHREAD_MUTEX_INITIALIZER;
    static int read;
    pthread_mutex_lock(&lock);
    if (!read)
        read = read_variables(resources, &variables, error, size) == 0;
    pthread_mutex_unlock(&lock);
    return read ? &variables : NULL;
}

fmi3Instance fmi3InstantiateCoSimulation(
    fmi3String name, fmi3String token, fmi3String location, fmi3Boolean visible,
    fmi3Boolean logging_on, fmi3Boolean event_mode_used, fmi3Boolean early_return_allowed,
    const fmi3ValueReference required[], size_t n_required, fmi3InstanceEnvironment environment,
    fmi3LogMessageCallback log_message, fmi3IntermediateUpdateCallback intermediate_update)
{
    (void)early_return_allowed, (void)required, (void)intermediate_update;
    char error[2048], resources[4096];
    struct runtime_record record;
    const struct variables *variables = NULL;
    if (event_mode_used || n_required) {
        early_message(name, environment, log_message,
                      event_mode_used ? "this FMU has no event mode (hasEventMode is false): "
                                        "instantiate it with eventModeUsed = false"
                                      : "this FMU provides no intermediate variables "
                                        "(providesIntermediateUpdate is false)");
        return NULL;
    }
    if (!name || !token || resources_folder(location, resources, sizeof resources)) {
        early_message(name, environment, log_message,
                      "fmi3InstantiateCoSimulation needs an instance name, the "
                      "instantiation token and the resource path");
        return NULL;
    }
    if (read_runtime_record(resources, &record, error, sizeof error) ||
        !(variables = variables_of(resources, error, sizeof error)) ||
        start_python(&record, error, sizeof error) ||
        slave_module_imports(resources, error, sizeof error)) {
        early_message(name, environment, log_message, error);
        return NULL;
    }
    struct instance3 *in3 = calloc(1, sizeof *in3);
    if (!in3)
        return NULL;
    struct instance *in = &in3->base;
    in3->environment = environment;
    in3->log_message = log_message;
    in3->variables = variables;
    return start_instance(in, name, token, location, resources, visible, logging_on,
                          (void *)log_message);
}

void fmi3FreeInstance(fmi3Instance instance)
{
    struct instance *in = ENTER(instance, fmi3FreeInstance);
    if (in)
        free_instance(in);
}

const char *fmi3GetVersion(void) { return fmi3Version; }

static fmi3Instance instantiate_other(fmi3String name, fmi3InstanceEnvironment environment,
                                      fmi3LogMessageCallback log_message, const char *function)
{
    char text[256];
    snprintf(text, sizeof text, "%s is not supported: this FMU is for co-simulation only "
                                "(fmi3InstantiateCoSimulation)", function);
    early_message(name, environment, log_message, text);
    return NULL;
}

fmi3Instance fmi3InstantiateModelExchange(fmi3String name, fmi3String token, fmi3String location,
                                          fmi3Boolean visible, fmi3Boolean logging_on,
                                          fmi3InstanceEnvironment environment,
                                          fmi3LogMessageCallback log_message)
{
    (void)token, (void)location, (void)visible, (void)logging_on;
    return instantiate_other(name, environment, log_message, "fmi3InstantiateModelExchange");
}

fmi3Instance fmi3InstantiateScheduledExecution(
    fmi3String name, fmi3String token, fmi3String location, fmi3Boolean visible,
    fmi3Boolean logging_on, fmi3InstanceEnvironment environment,
    fmi3LogMessageCallback log_message, fmi3ClockUpdateCallback clock_update,
    fmi3LockPreemptionCallback lock, fmi3UnlockPreemptionCallback unlock)
{
    (void)token, (void)location, (void)visible, (void)logging_on, (void)clock_update, (void)lock,
        (void)unlock;
    return instantiate_other(name, environment, log_message, "fmi3InstantiateScheduledExecution");
}
