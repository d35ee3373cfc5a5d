/* The FMU's binaries/linux64/<modelIdentifier>.so, its only binary: the FMI 2.0
 * runtime, which needs no pythonfmu binary.
 *
 * At fmi2Instantiate it uses the host's Python or starts one it finds on the
 * machine (python_runtime.c, python_discovery.c), imports the slave's script
 * module (slave_module.c), constructs the slave object and calls its Python
 * methods (slave_object.c) from the fmi2 calls (fmi2_calls.c), through a
 * per-instance FMI state machine (calls.c).  Every message the slave logs
 * arrives here and report.c routes it: warnings and refusals go to the host's
 * logger whether or not it asked for debug logging, and the status a call
 * returns is the worst one the slave logged during it.  The FMI 3.0 loader
 * (fmi3_loader.c) shares the state machine, the logging and the start.
 */
#define _GNU_SOURCE
#include "instance.h"

#include <math.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* The host's logger takes a printf format: a literal '%' must reach it doubled. */
int to_host(const struct instance *in, fmi2Status status, const char *category, const char *text)
{
    if (!in->host.logger)
        return 0;
    if (!strchr(text, '%')) {
        in->host.logger(in->host.componentEnvironment, in->name, status, category, text);
        return 1;
    }
    size_t n = 0;
    char *escaped = malloc(2 * strlen(text) + 1);
    if (!escaped)
        return 0;
    for (const char *c = text; *c; c++) {
        escaped[n++] = *c;
        if (*c == '%')
            escaped[n++] = '%';
    }
    escaped[n] = '\0';
    in->host.logger(in->host.componentEnvironment, in->name, status, category, escaped);
    free(escaped);
    return 1;
}

/* Messages before an instance exists still go to the host's logger. */
static void early_message(const fmi2CallbackFunctions *functions, const char *name,
                          const char *text)
{
    struct instance scratch = {.name = (char *)(name ? name : "?"), .model = MODEL_IDENTIFIER};
    if (functions)
        scratch.host = *functions;
    scratch.shared_proxy = is_shared_proxy((void *)scratch.host.logger);
    report(&scratch, fmi2Error, NULL, text);
}

fmi2Component fmi2Instantiate(fmi2String name, fmi2Type type, fmi2String guid,
                              fmi2String location, const fmi2CallbackFunctions *functions,
                              fmi2Boolean visible, fmi2Boolean logging_on)
{
    char error[2048], resources[4096];
    struct runtime_record record;
    if (type != fmi2CoSimulation) {
        early_message(functions, name, "this FMU supports co-simulation only (fmuType must be "
                                       "fmi2CoSimulation)");
        return NULL;
    }
    if (!name || !guid || resources_folder(location, resources, sizeof resources)) {
        early_message(functions, name, "fmi2Instantiate needs an instance name, the GUID and "
                                       "the resource location (a file URI)");
        return NULL;
    }
    if (read_runtime_record(resources, &record, error, sizeof error) ||
        start_python(&record, error, sizeof error) ||
        slave_module_imports(resources, error, sizeof error)) {
        early_message(functions, name, error);
        return NULL;
    }
    static struct fixed_parameters fixed;   /* the same for every instance of this FMU */
    static pthread_mutex_t fixed_lock = PTHREAD_MUTEX_INITIALIZER;
    static int fixed_read;
    pthread_mutex_lock(&fixed_lock);
    if (!fixed_read)
        fixed_read = read_fixed_parameters(resources, &fixed, error, sizeof error) == 0;
    int have_fixed = fixed_read;
    pthread_mutex_unlock(&fixed_lock);
    if (!have_fixed) {
        early_message(functions, name, error);
        return NULL;
    }
    struct instance *in = calloc(1, sizeof *in);
    if (!in)
        return NULL;
    in->fixed = &fixed;
    in->magic = INSTANCE_MAGIC;
    in->model = MODEL_IDENTIFIER;
    in->name = copy_of(name);
    in->guid = copy_of(guid);
    in->resources_uri = copy_of(location);
    in->resources = copy_of(resources);
    in->last_successful_time = NAN;
    in->visible = visible;
    in->logging_on = logging_on;
    const char *echo = getenv(ENV_STDERR);
    in->echo_stderr = echo && *echo && strcmp(echo, "0") != 0;
    if (functions)
        in->host = *functions;
    in->shared_proxy = is_shared_proxy((void *)in->host.logger);
    in->state = STATE_INSTANTIATED;
    if (slave_construct(in, resources)) {
        reportf(in, fmi2Error, "the slave could not be instantiated in %s: see the message "
                "before", python_in_use());
        free_instance(in);
        return NULL;
    }
    fast_attach(in, resources);
    if (record_matches_slave(in, resources, error, sizeof error)) {
        report(in, fmi2Error, NULL, error);
        free_instance(in);
        return NULL;
    }
    return in;
}
