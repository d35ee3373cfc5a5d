/* A C host that holds a Python of its own, as hosts that embed Python for their
 * own scripts do, and runs an FMU beside it:
 *
 *   embedding MODE (2|3) BINARY RESOURCES-URI TOKEN [LIBPYTHON]
 *
 * MODE, before the FMU (LIBPYTHON: the host's libpython3.X, or several
 * ':'-separated, the last one started where the mode starts one):
 *   loaded-global, loaded-local   dlopen it RTLD_GLOBAL or RTLD_LOCAL, never started
 *   finalized                     dlopen it RTLD_GLOBAL, Py_InitializeEx, Py_FinalizeEx
 *   running-local                 dlopen it RTLD_LOCAL and start it (a plugin's Python)
 * then instantiate, initialize, 100 steps, free, and for running-local the host's
 * Python runs a line of its own afterwards.  Prints "instance: ok|NULL", "steps: S",
 * "host python: R".  MODE finalize-after: the FMU's runtime starts Python, the
 * host finalizes it, then steps and instantiates again: prints "step before: S",
 * "finalized: R", "step after: S", "instantiate after: ok|NULL", "free after: done".
 * The runtime's messages go to stderr.  A signal instead of these lines is the
 * failure under test. */
#define _GNU_SOURCE
#include "fmi2.h"

#include <dlfcn.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static void log_fmi2(fmi2ComponentEnvironment env, fmi2String name, fmi2Status status,
                 fmi2String category, fmi2String message, ...)
{
    (void)env, (void)name, (void)category;
    fprintf(stderr, "LOG %d %s\n", status, message);
}

static void log_fmi3(void *env, int status, const char *category, const char *message)
{
    (void)env, (void)category;
    fprintf(stderr, "LOG %d %s\n", status, message);
}

#define SYMBOL(type, name) ((type)dlsym(so, name))
static void *so;
static int version;
static const char *uri, *token;
static const fmi2CallbackFunctions callbacks = {log_fmi2, calloc, free, NULL, NULL};

static void *instantiate(void)
{
    if (version == 2)
        return SYMBOL(void *(*)(const char *, int, const char *, const char *,
                                const fmi2CallbackFunctions *, int, int),
                      "fmi2Instantiate")("fmu", 1, token, uri, &callbacks, 0, 0);
    return SYMBOL(void *(*)(const char *, const char *, const char *, int, int, int, int,
                            const unsigned *, size_t, void *, void *, void *),
                  "fmi3InstantiateCoSimulation")("fmu", token, uri, 0, 0, 0, 0, NULL, 0, NULL,
                                                 (void *)log_fmi3, NULL);
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

static void free_instance(void *c)
{
    SYMBOL(void (*)(void *), version == 2 ? "fmi2FreeInstance" : "fmi3FreeInstance")(c);
}

/* The runtime starts Python; the host finalizes it under the instance. */
static int finalize_after(void)
{
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
    free_instance(c);
    printf("free after: done\n");
    return 0;
}

#define PY(type, name) ((type)dlsym(python, name))

int main(int argc, char **argv)
{
    const char *mode = argc > 1 ? argv[1] : "";
    int before = strcmp(mode, "finalize-after") != 0;
    if (argc != 6 + before || (strcmp(argv[2], "2") && strcmp(argv[2], "3"))) {
        fprintf(stderr, "usage: embedding MODE (2|3) BINARY RESOURCES-URI TOKEN [LIBPYTHON]\n");
        return 2;
    }
    version = atoi(argv[2]), uri = argv[4], token = argv[5];
    void *python = NULL;
    if (before) {
        int local = strstr(mode, "local") != NULL;
        for (char *save, *one = strtok_r(argv[6], ":", &save); one;
             one = strtok_r(NULL, ":", &save))
            if (!(python = dlopen(one, RTLD_NOW | (local ? RTLD_LOCAL : RTLD_GLOBAL)))) {
                fprintf(stderr, "dlopen %s: %s\n", one, dlerror());
                return 2;
            }
        if (strcmp(mode, "finalized") == 0 || strcmp(mode, "running-local") == 0)
            PY(void (*)(int), "Py_InitializeEx")(0);
        if (strcmp(mode, "finalized") == 0)
            PY(int (*)(void), "Py_FinalizeEx")();
    }
    if (!(so = dlopen(argv[3], RTLD_NOW | RTLD_LOCAL))) {
        fprintf(stderr, "dlopen: %s\n", dlerror());
        return 2;
    }
    if (!before)
        return finalize_after();
    void *c = instantiate();
    printf("instance: %s\n", c ? "ok" : "NULL");
    int status = c ? initialize(c) : -1;
    for (int k = 0; c && status == 0 && k < 100; k++)
        status = step(c, k * 1e-3);
    printf("steps: %d\n", status);
    if (c)
        free_instance(c);
    if (strcmp(mode, "running-local") == 0)
        printf("host python: %d\n", PY(int (*)(const char *), "PyRun_SimpleString")(
                                         "import json; json.dumps({'host': 'python'})"));
    return 0;
}
