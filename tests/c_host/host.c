/* A minimal FMI 2.0 co-simulation host, loading the FMU as a C/C++ tool does
 * (dlopen RTLD_NOW | RTLD_LOCAL, no Python of its own).  Usage, with DIR the
 * extracted FMU:
 *
 *   host run DIR STEPS DT [name=value ...]  CSV of all outputs (FMPy's layout)
 *   host last DIR STEPS DT [name=value ...] the same run, every output read at each
 *                                           step, only the header and the last row printed
 *   host bad DIR NAME VALUE                 one step after a bad input, logging off
 *   host instantiate DIR                    instantiate only: "instance ok|NULL"
 *   host threads DIR STEPS                  two threads, one instance each; one
 *                                           instance driven from two threads in turn
 *   host cycles DIR N                       N instantiate/step/free cycles
 *   host fuzz DIR SEED COUNT                random legal and illegal calls (fuzz.c)
 *   host bench DIR STEPS [name=value ...]   µs per (set the named inputs, doStep of
 *                                           1 ms, get every output)
 *
 * Logger calls go to stderr as "LOG <status> <category>: <message>".
 */
#include "host.h"

#include <dlfcn.h>
#include <math.h>
#include <pthread.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

struct fmu fmu;
int log_calls;
char last_message[2048];

static void logger(fmi2ComponentEnvironment env, fmi2String name, fmi2Status status,
                   fmi2String category, fmi2String format, ...)
{
    (void)env, (void)name;
    va_list args;
    va_start(args, format);
    vsnprintf(last_message, sizeof last_message, format, args);
    va_end(args);
    __atomic_add_fetch(&log_calls, 1, __ATOMIC_SEQ_CST);
    fprintf(stderr, "LOG %d %s: %s\n", status, category ? category : "-", last_message);
}

const fmi2CallbackFunctions callbacks = {logger, calloc, free, NULL, NULL};

static void read_model_description(const char *dir)
{
    char path[4096];
    snprintf(path, sizeof path, "%s/modelDescription.xml", dir);
    FILE *file = fopen(path, "r");
    if (!file)
        fail("cannot read %s", path);
    static char xml[1 << 20];
    size_t n = fread(xml, 1, sizeof xml - 1, file);
    xml[n] = '\0';
    fclose(file);
    char *identifier = strstr(xml, "modelIdentifier=\"");
    if (!identifier || sscanf(identifier, "modelIdentifier=\"%63[^\"]", fmu.identifier) != 1)
        fail("no modelIdentifier in %s", path);
    char *guid = strstr(xml, "guid=\"");
    if (!guid || sscanf(guid, "guid=\"%127[^\"]", fmu.guid) != 1)
        fail("no guid in %s", path);
    for (char *v = strstr(xml, "<ScalarVariable"); v; v = strstr(v + 1, "<ScalarVariable")) {
        if (fmu.n_variables == (int)(sizeof fmu.variables / sizeof fmu.variables[0]))
            fail("more than %d variables in %s", fmu.n_variables, path);
        struct variable *var = &fmu.variables[fmu.n_variables++];
        char *end = strchr(v, '>');
        char *name = strstr(v, " name=\""), *vr = strstr(v, "valueReference=\"");
        char *causality = strstr(v, "causality=\"");
        sscanf(name, " name=\"%63[^\"]", var->name);
        sscanf(vr, "valueReference=\"%u", &var->vr);
        if (causality && causality < end)
            sscanf(causality, "causality=\"%15[^\"]", var->causality);
    }
}

void load(const char *dir)
{
    char path[4096];
    read_model_description(dir);
    snprintf(path, sizeof path, "%s/binaries/linux64/%s.so", dir, fmu.identifier);
    void *handle = dlopen(path, RTLD_NOW | RTLD_LOCAL);
    if (!handle)
        fail("dlopen: %s", dlerror());
#define RESOLVE(name)                                                                     \
    if (!(fmu.name = (__typeof__(fmu.name))dlsym(handle, "fmi2" #name)))                  \
        fail("missing fmi2%s", #name);
    FMI_FUNCTIONS(RESOLVE)
    snprintf(fmu.resources, sizeof fmu.resources, "file://%s/resources", dir);
}

fmi2ValueReference reference(const char *name)
{
    for (int i = 0; i < fmu.n_variables; i++)
        if (strcmp(fmu.variables[i].name, name) == 0)
            return fmu.variables[i].vr;
    fail("no variable %s", name);
    return 0;
}

int outputs(fmi2ValueReference *vr)
{
    int n = 0;
    for (int i = 0; i < fmu.n_variables; i++)
        if (strcmp(fmu.variables[i].causality, "output") == 0)
            vr[n++] = fmu.variables[i].vr;
    return n;
}

fmi2Component start(const char *name, fmi2Boolean logging_on)
{
    fmi2Component c = fmu.Instantiate(name, fmi2CoSimulation, fmu.guid, fmu.resources,
                                      &callbacks, fmi2False, logging_on);
    if (!c)
        fail("fmi2Instantiate returned NULL");
    check(fmu.SetupExperiment(c, fmi2False, 0.0, 0.0, fmi2False, 0.0), "SetupExperiment");
    return c;
}

void initialize(fmi2Component c)
{
    check(fmu.EnterInitializationMode(c), "EnterInitializationMode");
    check(fmu.ExitInitializationMode(c), "ExitInitializationMode");
}

/* name=value arguments: their value references and values. */
static void parse_settings(int n, char **settings, fmi2ValueReference *vr, double *values)
{
    if (n > 64)
        fail("at most 64 name=value settings, got %d", n);
    for (int i = 0; i < n; i++) {
        char name[64];
        if (sscanf(settings[i], "%63[^=]=%lf", name, &values[i]) != 2)
            fail("expected name=value, got %s", settings[i]);
        vr[i] = reference(name);
    }
}

/* The communication points FMPy's simulate_fmu uses: start + k * dt. */
static int run(const char *dir, int steps, double dt, int n_settings, char **settings,
               int every_row)
{
    load(dir);
    fmi2Component c = start("run", fmi2False);
    fmi2ValueReference set[64];
    double values[64];
    parse_settings(n_settings, settings, set, values);
    for (int i = 0; i < n_settings; i++)
        check(fmu.SetReal(c, &set[i], 1, &values[i]), "SetReal");
    initialize(c);
    fmi2ValueReference vr[64];
    double y[64];
    int n = outputs(vr);
    printf("\"time\"");
    for (int i = 0; i < fmu.n_variables; i++)
        if (strcmp(fmu.variables[i].causality, "output") == 0)
            printf(",\"%s\"", fmu.variables[i].name);
    printf("\n");
    double time = 0.0;
    for (int k = 0; k <= steps; k++) {
        check(fmu.GetReal(c, vr, n, y), "GetReal");
        if (every_row || k == steps) {
            printf("%.17g", time);
            for (int i = 0; i < n; i++)
                printf(",%.17g", y[i]);
            printf("\n");
        }
        if (k == steps)
            break;
        double next = (k + 1) * dt;
        check(fmu.DoStep(c, time, next - time, fmi2True), "DoStep");
        time = next;
    }
    check(fmu.Terminate(c), "Terminate");
    fmu.FreeInstance(c);
    return 0;
}

static int bad(const char *dir, const char *name, double value)
{
    load(dir);
    fmi2Component c = start("bad", fmi2False);
    initialize(c);
    fmi2ValueReference vr = reference(name);
    int before = log_calls;
    fmi2Status set = fmu.SetReal(c, &vr, 1, &value);
    fmi2Status step = fmu.DoStep(c, 0.0, 1e-3, fmi2True);
    printf("set %d step %d logger_calls %d\nmessage %s\n", set, step, log_calls - before,
           last_message);
    fmu.FreeInstance(c);
    return 0;
}

static int instantiate_only(const char *dir)
{
    load(dir);
    fmi2Component c = fmu.Instantiate("probe", fmi2CoSimulation, fmu.guid, fmu.resources,
                                      &callbacks, fmi2False, fmi2False);
    printf("instance %s logger_calls %d\n", c ? "ok" : "NULL", log_calls);
    if (c)
        fmu.FreeInstance(c);
    return 0;
}

static int cycles(const char *dir, int n)
{
    load(dir);
    for (int i = 0; i < n; i++) {
        fmi2Component c = start("cycle", fmi2False);
        initialize(c);
        for (int k = 0; k < 5; k++)
            check(fmu.DoStep(c, k * 1e-3, 1e-3, fmi2True), "DoStep");
        check(fmu.Terminate(c), "Terminate");
        fmu.FreeInstance(c);
    }
    printf("cycles %d ok\n", n);
    return 0;
}

static double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return t.tv_sec + 1e-9 * t.tv_nsec;
}

static int bench(const char *dir, int steps, int n_inputs, char **inputs)
{
    load(dir);
    fmi2Component c = start("bench", fmi2False);
    initialize(c);
    fmi2ValueReference in[64], out[64];
    double values[64], y[64];
    parse_settings(n_inputs, inputs, in, values);
    int n = outputs(out);
    double began = now(), h = 1e-3;
    for (int k = 0; k < steps; k++) {
        fmu.SetReal(c, in, n_inputs, values);
        check(fmu.DoStep(c, k * h, h, fmi2True), "DoStep");
        fmu.GetReal(c, out, n, y);
    }
    printf("%.3f us/step\n", 1e6 * (now() - began) / steps);
    fmu.FreeInstance(c);
    return 0;
}

int main(int argc, char **argv)
{
    setvbuf(stdout, NULL, _IOFBF, 1 << 16);
    if (argc >= 5 && strcmp(argv[1], "run") == 0)
        return run(argv[2], atoi(argv[3]), atof(argv[4]), argc - 5, argv + 5, 1);
    if (argc >= 5 && strcmp(argv[1], "last") == 0)
        return run(argv[2], atoi(argv[3]), atof(argv[4]), argc - 5, argv + 5, 0);
    if (argc == 5 && strcmp(argv[1], "bad") == 0)
        return bad(argv[2], argv[3], strtod(argv[4], NULL));
    if (argc == 5 && strcmp(argv[1], "refusal") == 0)
        return refusal(argv[2], argv[3], strtod(argv[4], NULL));
    if (argc == 3 && strcmp(argv[1], "instantiate") == 0)
        return instantiate_only(argv[2]);
    if (argc == 4 && strcmp(argv[1], "threads") == 0)
        return threads(argv[2], atoi(argv[3]));
    if (argc == 4 && strcmp(argv[1], "cycles") == 0)
        return cycles(argv[2], atoi(argv[3]));
    if (argc == 5 && strcmp(argv[1], "fuzz") == 0)
        return fuzz(argv[2], strtoul(argv[3], NULL, 10), atoi(argv[4]));
    if (argc >= 4 && strcmp(argv[1], "bench") == 0)
        return bench(argv[2], atoi(argv[3]), argc - 4, argv + 4);
    fprintf(stderr, "usage: see the comment at the top of host.c\n");
    return 2;
}
