/* Several FMUs (different binaries, FMI 2.0 and 3.0 mixed) loaded RTLD_LOCAL by a
 * C host without Python and first instantiated at the same moment, one thread
 * each, as co-simulation masters instantiate a system's FMUs in parallel.
 *
 *   concurrent (serial|together) FMU...
 *   FMU = version|binary|resources-uri|guid|vr=value,...|out-vr,...
 *
 * Each FMU: instantiate, set the inputs, initialize, 200 steps of 1 ms, print
 * its outputs (%.17g) in argument order.  "serial" runs them one after the
 * other, "together" from threads released at once; the outputs must agree. */
#define _GNU_SOURCE
#include <dlfcn.h>
#include <pthread.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef void (*logger2)(void *, const char *, int, const char *, const char *, ...);
struct callbacks2 {
    logger2 logger;
    void *(*allocate)(size_t, size_t);
    void (*release)(void *);
    void *step_finished;
    void *environment;
};

#define MAX_VALUES 64
struct job {
    int version;
    char *binary, *uri, *guid;
    unsigned in_vr[MAX_VALUES], out_vr[MAX_VALUES];
    double in_value[MAX_VALUES], out_value[MAX_VALUES];
    int n_in, n_out;
    const char *failure;
    pthread_barrier_t *gate;
};

static void log2(void *env, const char *name, int status, const char *category,
                 const char *message, ...)
{
    (void)env, (void)category;
    fprintf(stderr, "[%s %d] %s\n", name, status, message);
}

static void log3(void *env, int status, const char *category, const char *message)
{
    (void)env, (void)category;
    fprintf(stderr, "[fmi3 %d] %s\n", status, message);
}

#define SYMBOL(handle, type, name) ((type)dlsym(handle, name))

static const char *run2(struct job *job, void *so)
{
    struct callbacks2 callbacks = {log2, calloc, free, NULL, NULL};
    void *c = SYMBOL(so, void *(*)(const char *, int, const char *, const char *,
                                   const struct callbacks2 *, int, int),
                     "fmi2Instantiate")("fmu", 1, job->guid, job->uri, &callbacks, 0, 0);
    if (!c)
        return "fmi2Instantiate returned NULL";
    int (*set)(void *, const unsigned *, size_t, const double *) =
        SYMBOL(so, int (*)(void *, const unsigned *, size_t, const double *), "fmi2SetReal");
    int (*get)(void *, const unsigned *, size_t, double *) =
        SYMBOL(so, int (*)(void *, const unsigned *, size_t, double *), "fmi2GetReal");
    int (*call)(void *) = SYMBOL(so, int (*)(void *), "fmi2EnterInitializationMode");
    const char *failure = NULL;
    if (set(c, job->in_vr, job->n_in, job->in_value) || call(c) ||
        SYMBOL(so, int (*)(void *), "fmi2ExitInitializationMode")(c))
        failure = "initialization failed";
    int (*step)(void *, double, double, int) =
        SYMBOL(so, int (*)(void *, double, double, int), "fmi2DoStep");
    for (int k = 0; !failure && k < 200; k++)
        if (step(c, k * 1e-3, 1e-3, 1))
            failure = "fmi2DoStep failed";
    if (!failure && get(c, job->out_vr, job->n_out, job->out_value))
        failure = "fmi2GetReal failed";
    SYMBOL(so, void (*)(void *), "fmi2FreeInstance")(c);
    return failure;
}

static const char *run3(struct job *job, void *so)
{
    void *c = SYMBOL(so, void *(*)(const char *, const char *, const char *, int, int, int, int,
                                   const unsigned *, size_t, void *, void *, void *),
                     "fmi3InstantiateCoSimulation")("fmu", job->guid, job->uri, 0, 0, 0, 0,
                                                    NULL, 0, NULL, (void *)log3, NULL);
    if (!c)
        return "fmi3InstantiateCoSimulation returned NULL";
    int (*set)(void *, const unsigned *, size_t, const double *, size_t) =
        SYMBOL(so, int (*)(void *, const unsigned *, size_t, const double *, size_t),
               "fmi3SetFloat64");
    int (*get)(void *, const unsigned *, size_t, double *, size_t) =
        SYMBOL(so, int (*)(void *, const unsigned *, size_t, double *, size_t),
               "fmi3GetFloat64");
    const char *failure = NULL;
    if (set(c, job->in_vr, job->n_in, job->in_value, job->n_in) ||
        SYMBOL(so, int (*)(void *, int, double, double, int, double),
               "fmi3EnterInitializationMode")(c, 0, 0, 0, 0, 0) ||
        SYMBOL(so, int (*)(void *), "fmi3ExitInitializationMode")(c))
        failure = "initialization failed";
    int (*step)(void *, double, double, int, int *, int *, int *, double *) =
        SYMBOL(so, int (*)(void *, double, double, int, int *, int *, int *, double *),
               "fmi3DoStep");
    for (int k = 0; !failure && k < 200; k++) {
        int event, terminate, early;
        double last;
        if (step(c, k * 1e-3, 1e-3, 1, &event, &terminate, &early, &last))
            failure = "fmi3DoStep failed";
    }
    if (!failure && get(c, job->out_vr, job->n_out, job->out_value, job->n_out))
        failure = "fmi3GetFloat64 failed";
    SYMBOL(so, void (*)(void *), "fmi3FreeInstance")(c);
    return failure;
}

static void *run(void *argument)
{
    struct job *job = argument;
    void *so = dlopen(job->binary, RTLD_NOW | RTLD_LOCAL);
    if (!so) {
        job->failure = "dlopen failed";
        return NULL;
    }
    if (job->gate)
        pthread_barrier_wait(job->gate);
    job->failure = job->version == 3 ? run3(job, so) : run2(job, so);
    return NULL;
}

static void parse(struct job *job, char *text)
{
    char *fields[6];
    for (int i = 0; i < 6; i++)
        fields[i] = strsep(&text, "|");
    if (!fields[5]) {
        fprintf(stderr, "bad FMU argument\n");
        exit(2);
    }
    job->version = atoi(fields[0]);
    job->binary = fields[1], job->uri = fields[2], job->guid = fields[3];
    for (char *item; (item = strsep(&fields[4], ",")) && *item && job->n_in < MAX_VALUES;
         job->n_in++)
        sscanf(item, "%u=%lf", &job->in_vr[job->n_in], &job->in_value[job->n_in]);
    for (char *item; (item = strsep(&fields[5], ",")) && *item && job->n_out < MAX_VALUES;
         job->n_out++)
        job->out_vr[job->n_out] = (unsigned)strtoul(item, NULL, 10);
}

int main(int argc, char **argv)
{
    if (argc < 3 || (strcmp(argv[1], "serial") && strcmp(argv[1], "together"))) {
        fprintf(stderr, "usage: concurrent (serial|together) FMU...\n");
        return 2;
    }
    int n = argc - 2, together = strcmp(argv[1], "together") == 0;
    struct job *jobs = calloc((size_t)n, sizeof *jobs);
    pthread_t *threads = calloc((size_t)n, sizeof *threads);
    pthread_barrier_t gate;
    pthread_barrier_init(&gate, NULL, (unsigned)n);
    for (int i = 0; i < n; i++) {
        parse(&jobs[i], argv[i + 2]);
        if (together) {
            jobs[i].gate = &gate;
            pthread_create(&threads[i], NULL, run, &jobs[i]);
        } else
            run(&jobs[i]);
    }
    int failed = 0;
    for (int i = 0; i < n; i++) {
        if (together)
            pthread_join(threads[i], NULL);
        if (jobs[i].failure) {
            printf("fmu %d: %s\n", i, jobs[i].failure);
            failed = 1;
            continue;
        }
        printf("fmu %d:", i);
        for (int k = 0; k < jobs[i].n_out; k++)
            printf(" %.17g", jobs[i].out_value[k]);
        printf("\n");
    }
    return failed;
}
