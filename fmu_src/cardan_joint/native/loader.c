/* The FMU's binaries/linux64/<modelIdentifier>.so: makes pythonfmu's binary,
 * shipped beside it as <modelIdentifier>_pythonfmu.so, run in any FMI host.
 *
 * At fmi2Instantiate it uses the host's Python or starts one it finds on the
 * machine (python_runtime.c, python_discovery.c), then loads pythonfmu's binary and forwards the fmi2 calls
 * (fmi2_calls.c) through a per-instance FMI state machine.  pythonfmu always
 * gets this file's logger with logging on, so every message of the slave
 * arrives here: warnings and refusals go to the host's logger whether or not
 * it asked for debug logging, and the status a call returns is the worst one
 * the slave logged during it (pythonfmu itself can only return OK or Discard).
 */
#define _GNU_SOURCE
#include "instance.h"

#include <dlfcn.h>
#include <limits.h>
#include <pthread.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

struct slave_api slave;

static const char *const STATUS_NAMES[] = {"OK", "Warning", "Discard", "Error", "Fatal", "Pending"};
static const char *const STATUS_CATEGORIES[] = {
    "logAll", "logStatusWarning", "logStatusDiscard", "logStatusError", "logStatusFatal", "logAll"};

static int category_enabled(const struct instance *in, const char *category)
{
    if (!in->logging_on)
        return 0;
    if (in->n_categories == 0 || strcmp(category, "logAll") == 0)
        return 1;
    for (size_t i = 0; i < in->n_categories; i++)
        if (strcmp(in->categories[i], category) == 0 || strcmp(in->categories[i], "logAll") == 0)
            return 1;
    return 0;
}

/* The host's logger takes a printf format: a literal '%' must reach it doubled. */
static void to_host(const struct instance *in, fmi2Status status, const char *category,
                    const char *text)
{
    if (!strchr(text, '%')) {
        in->host.logger(in->host.componentEnvironment, in->name, status, category, text);
        return;
    }
    size_t n = 0;
    char *escaped = malloc(2 * strlen(text) + 1);
    if (!escaped)
        return;
    for (const char *c = text; *c; c++) {
        escaped[n++] = *c;
        if (*c == '%')
            escaped[n++] = '%';
    }
    escaped[n] = '\0';
    in->host.logger(in->host.componentEnvironment, in->name, status, category, escaped);
    free(escaped);
}

void report(struct instance *in, fmi2Status status, const char *category, const char *text)
{
    unsigned index = status <= fmi2Pending ? (unsigned)status : (unsigned)fmi2Fatal;
    if (status > in->worst)
        in->worst = status;
    if (!category || !*category)
        category = STATUS_CATEGORIES[index];
    int important = status != fmi2OK && status != fmi2Pending;
    if (!important && !category_enabled(in, category))
        return;
    int to_logger = in->host.logger && (in->logging_on || !in->shared_proxy);
    if (to_logger)
        to_host(in, status, category, text);
    if (in->echo_stderr || (!to_logger && important))
        fprintf(stderr, "[%s %s] %s: %s\n", in->model, in->name, STATUS_NAMES[index], text);
}

void reportf(struct instance *in, fmi2Status status, const char *format, ...)
{
    char text[1024];
    va_list args;
    va_start(args, format);
    vsnprintf(text, sizeof text, format, args);
    va_end(args);
    report(in, status, NULL, text);
}

/* pythonfmu calls it with the message as its format and no arguments. */
static void from_slave(fmi2ComponentEnvironment environment, fmi2String name,
                       fmi2Status status, fmi2String category, fmi2String message, ...)
{
    (void)name;
    report(environment, status, category, message ? message : "");
}

/* pythonfmu 0.7.0 resets its static shared_ptr<PyState> twice at exit: once in
 * the destructor registered with __cxa_atexit when its binary is loaded, then in
 * its __attribute__((destructor)), which frees it again ("free(): corrupted
 * unsorted chunks").  This handler, registered after that load, runs first:
 * pythonfmu's exported finalizePythonInterpreter empties the pointer before it
 * releases it, so both later resets find nothing to free. */
static void empty_slave_state_at_exit(void)
{
    if (slave.finalize)
        slave.finalize();
}

static int load_slave_library(const char *model, char *error, size_t size)
{
    static pthread_mutex_t lock = PTHREAD_MUTEX_INITIALIZER;
    int result = 0;
    pthread_mutex_lock(&lock);
    if (!slave.handle) {
        Dl_info self;
        char path[PATH_MAX];
        dladdr((void *)&load_slave_library, &self);
        snprintf(path, sizeof path, "%s", self.dli_fname);
        char *slash = strrchr(path, '/');
        snprintf(slash ? slash + 1 : path, sizeof path - (size_t)(slash ? slash + 1 - path : 0),
                 "%s_pythonfmu.so", model);
        void *handle = dlopen(path, RTLD_NOW | RTLD_LOCAL);
        if (!handle) {
            snprintf(error, size, "cannot load pythonfmu's binary: %s", dlerror());
            result = -1;
        } else if (resolve_slave_api(handle, error, size)) {
            result = -1;
        } else {
            slave.finalize = (void (*)(void))dlsym(handle, "finalizePythonInterpreter");
            atexit(empty_slave_state_at_exit);
            slave.handle = handle;
        }
    }
    pthread_mutex_unlock(&lock);
    return result;
}

/* FMPy's logger proxy (fmpy/logging) keeps ONE target for the whole process:
 * the logger of the last callbacks it wrapped, which simulate_fmu frees when
 * it returns. Calling it for an instance whose host did not turn logging on
 * may jump into freed memory, so such messages go to stderr instead. */
static int is_shared_proxy(fmi2CallbackLogger logger)
{
    Dl_info where;
    return logger && dladdr((void *)logger, &where) && where.dli_fname &&
           strstr(where.dli_fname, "/fmpy/logging/");
}

/* Messages before an instance exists still go to the host's logger. */
static void early_message(const fmi2CallbackFunctions *functions, const char *name,
                          const char *text)
{
    struct instance scratch = {.name = (char *)(name ? name : "?"), .model = MODEL_IDENTIFIER};
    if (functions)
        scratch.host = *functions;
    scratch.shared_proxy = is_shared_proxy(scratch.host.logger);
    report(&scratch, fmi2Error, NULL, text);
}

char *copy_of(const char *text)
{
    return strdup(text ? text : "");
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
        load_slave_library(MODEL_IDENTIFIER, error, sizeof error)) {
        early_message(functions, name, error);
        return NULL;
    }
    static struct fixed_parameters fixed;   /* the same for every instance of this FMU */
    static pthread_mutex_t fixed_lock = PTHREAD_MUTEX_INITIALIZER;
    static int fixed_read;
    pthread_mutex_lock(&fixed_lock);
    if (!fixed_read)
        fixed_read = read_fixed_parameters(resources, &fixed) == 0;
    pthread_mutex_unlock(&fixed_lock);
    struct instance *in = calloc(1, sizeof *in);
    if (!in)
        return NULL;
    in->fixed = &fixed;
    in->magic = INSTANCE_MAGIC;
    in->model = MODEL_IDENTIFIER;
    in->name = copy_of(name);
    in->guid = copy_of(guid);
    in->resources_uri = copy_of(location);
    in->visible = visible;
    in->logging_on = logging_on;
    const char *echo = getenv(ENV_STDERR);
    in->echo_stderr = echo && *echo && strcmp(echo, "0") != 0;
    if (functions)
        in->host = *functions;
    in->shared_proxy = is_shared_proxy(in->host.logger);
    in->to_slave = in->host;
    in->to_slave.logger = from_slave;
    in->to_slave.componentEnvironment = in;
    in->state = STATE_INSTANTIATED;
    in->slave = slave.instantiate(in->name, fmi2CoSimulation, in->guid, in->resources_uri,
                                  &in->to_slave, in->visible, fmi2True);
    if (!in->slave) {
        reportf(in, fmi2Error, "the slave could not be instantiated in %s: see the message "
                "before", python_in_use());
        free_instance(in);
        return NULL;
    }
    return in;
}
