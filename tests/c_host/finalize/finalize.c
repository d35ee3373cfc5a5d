/* A C host that finalizes the Python the FMU's runtime started in it, then goes
 * on calling the FMU, as a host that embeds Python for its own scripts might:
 *
 *   finalize (2|3) BINARY RESOURCES-URI TOKEN
 *
 * Instantiate, initialize and one step; Py_FinalizeEx on the process's Python
 * (the runtime loaded it RTLD_GLOBAL); then one more step and a new instance.
 * Prints "step before: S", "finalized: R", "step after: S", "instantiate
 * after: ok|NULL", "free after: done"; the runtime's messages go to stderr.
 * A signal instead of these lines is the failure under test. */
#define _GNU_SOURCE
#include "fmi2.h"

#include <dlfcn.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static void log2(fmi2ComponentEnvironment env, fmi2String name, fmi2Status status,
                 fmi2String category, fmi2String message, ...)
{
    (void)env, (void)name, (void)category;
    fprintf(stderr, "LOG %d %s\n", status, message);
}

static void log3(void *env, int status, const char *category, const char *message)
{
    (void)env, (void)category;
    fprintf(stderr, "LOG %d %s\n", status, message);
}

#define SYMBOL(type, name) ((type)dlsym(so, name))
static void *so;
static int version;
static const char *uri, *token;
static const fmi2CallbackFunctions callbacks = {log2, calloc, free, NULL, NULL};

static void *instantiate(void)
{
    if (version == 2)
        return SYMBOL(void *(*)(const char *, int, const char *, const char *,
                                const fmi2CallbackFunctions *, int, int),
                      "fmi2Instantiate")("fmu", 1, token, uri, &callbacks, 0, 0);
    return SYMBOL(void *(*)(const char *, const char *, const char *, int, int, int, int,
                            const unsigned *, size_t, void *, void *, void *),
                  "fmi3InstantiateCoSimulation")("fmu", token, uri, 0, 0, 0, 0, NULL, 0, NULL,
                                                 (void *)log3, NULL);
}

static int initialize(void *c)
{
    if (version == 2)
        return SYMBOL(int (*)(void *, int, double, double, int, double),
                      "fmi2SetupExperiment")(c, 0, 0, 0, 0, 0) ||
               SYMBOL(int (*)(void *), "fmi2EnterInitializationMode")(c) ||
               SYMBOL(int (*)(void *), "fmi2ExitInitializationMode")(c);
    return SYMBOL(int (*)(void *, int, double, double, int, double),
                  "fmi3EnterInitializationMode")(c, 0, 0, 0, 0, 0) ||
           SYMBOL(int (*)(void *), "fmi3ExitInitializationMode")(c);
}

static int step(void *c, double time)
{
    if (version == 2)
        return SYMBOL(int (*)(void *, double, double, int), "fmi2DoStep")(c, time, 1e-3, 1);
    int event, terminate, early;
    double last;
    return SYMBOL(int (*)(void *, double, double, int, int *, int *, int *, double *),
                  "fmi3DoStep")(c, time, 1e-3, 1, &event, &terminate, &early, &last);
}

int main(int argc, char **argv)
{
    if (argc != 5 || (strcmp(argv[1], "2") && strcmp(argv[1], "3"))) {
        fprintf(stderr, "usage: finalize (2|3) BINARY RESOURCES-URI TOKEN\n");
        return 2;
    }
    version = atoi(argv[1]), uri = argv[3], token = argv[4];
    if (!(so = dlopen(argv[2], RTLD_NOW | RTLD_LOCAL))) {
        fprintf(stderr, "dlopen: %s\n", dlerror());
        return 2;
    }
    void *c = instantiate();
    if (!c || initialize(c)) {
        fprintf(stderr, "the FMU did not start\n");
        return 2;
    }
    printf("step before: %d\n", step(c, 0.0));
    int (*finalize)(void) = (int (*)(void))dlsym(RTLD_DEFAULT, "Py_FinalizeEx");
    int (*ensure)(void) = (int (*)(void))dlsym(RTLD_DEFAULT, "PyGILState_Ensure");
    if (!finalize || !ensure) {
        fprintf(stderr, "no Python in the process's global scope\n");
        return 2;
    }
    ensure(); /* Py_FinalizeEx wants the GIL and a thread state, as any embedder holds them */
    printf("finalized: %d\n", finalize());
    fflush(stdout);
    printf("step after: %d\n", step(c, 1e-3));
    fflush(stdout);
    printf("instantiate after: %s\n", instantiate() ? "ok" : "NULL");
    fflush(stdout);
    SYMBOL(void (*)(void *), version == 2 ? "fmi2FreeInstance" : "fmi3FreeInstance")(c);
    printf("free after: done\n");
    return 0;
}
