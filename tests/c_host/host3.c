/* A minimal FMI 3.0 co-simulation host, loading the FMU as a C/C++ tool does
 * (dlopen RTLD_NOW | RTLD_LOCAL, no Python of its own).  Usage, with DIR the
 * extracted FMU:
 *
 *   host3 run DIR STEPS DT [name=value ...]  CSV of all outputs, arrays by element
 *   host3 bad DIR NAME VALUE                 one step after a bad input, logging off
 *   host3 instantiate DIR                    instantiate only: "instance ok|NULL"
 *   host3 misuse DIR                         unsupported calls, wrong counts, wrong order
 *   host3 threads DIR STEPS                  two instances on two threads = one alone
 *                                            (threads3.c)
 *   host3 cycles DIR N                       N instantiate/step/free cycles
 *   host3 fuzz DIR SEED COUNT                random legal and illegal calls (fuzz3.c)
 *
 * Logger calls go to stderr as "LOG <status> <category>: <message>".
 */
#include "host3.h"

#include <dlfcn.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

struct fmu3 fmu;
int log_calls;
char last_message[2048];

void logger(fmi3InstanceEnvironment env, fmi3Status status, fmi3String category,
                   fmi3String message)
{
    (void)env;
    snprintf(last_message, sizeof last_message, "%s", message);
    __atomic_add_fetch(&log_calls, 1, __ATOMIC_SEQ_CST);
    fprintf(stderr, "LOG %d %s: %s\n", status, category ? category : "-", message);
}

static void attribute(const char *from, const char *end, const char *key, const char *format,
                      void *value)
{
    const char *found = strstr(from, key);
    if (found && found < end)
        sscanf(found + strlen(key), format, value);
}

void load(const char *dir)
{
    char path[4096];
    snprintf(path, sizeof path, "%s/modelDescription.xml", dir);
    FILE *file = fopen(path, "r");
    if (!file)
        fail("cannot read %s", path);
    static char xml[1 << 20];
    xml[fread(xml, 1, sizeof xml - 1, file)] = '\0';
    fclose(file);
    attribute(xml, xml + strlen(xml), "modelIdentifier=\"", "%63[^\"]", fmu.identifier);
    attribute(xml, xml + strlen(xml), "instantiationToken=\"", "%127[^\"]", fmu.token);
    for (char *v = strstr(xml, "<Float64 "); v; v = strstr(v + 1, "<Float64 ")) {
        struct variable *var = &fmu.variables[fmu.n_variables++];
        char *end = strchr(v, '>'), *close = strstr(v, "</Float64>");
        attribute(v, end, " name=\"", "%63[^\"]", var->name);
        attribute(v, end, "valueReference=\"", "%u", &var->vr);
        attribute(v, end, "causality=\"", "%15[^\"]", var->causality);
        var->size = 1;
        if (end[-1] != '/' && close)
            attribute(end, close, "<Dimension start=\"", "%d", &var->size);
    }
    snprintf(path, sizeof path, "%s/binaries/x86_64-linux/%s.so", dir, fmu.identifier);
    void *handle = dlopen(path, RTLD_NOW | RTLD_LOCAL);
    if (!handle)
        fail("dlopen: %s", dlerror());
#define RESOLVE(name)                                                                      \
    if (!(fmu.name = (fmi3##name##TYPE *)dlsym(handle, "fmi3" #name)))                    \
        fail("missing fmi3%s", #name);
    FUNCTIONS(RESOLVE)
    snprintf(fmu.resources, sizeof fmu.resources, "%s/resources/", dir);
}

const struct variable *variable(const char *name)
{
    for (int i = 0; i < fmu.n_variables; i++)
        if (strcmp(fmu.variables[i].name, name) == 0)
            return &fmu.variables[i];
    fail("no variable %s", name);
    return NULL;
}

fmi3Instance instantiate(const char *name, fmi3Boolean logging_on)
{
    return fmu.InstantiateCoSimulation(name, fmu.token, fmu.resources, fmi3False, logging_on,
                                       fmi3False, fmi3False, NULL, 0, NULL, logger, NULL);
}

fmi3Instance start(const char *name)
{
    fmi3Instance c = instantiate(name, fmi3False);
    if (!c)
        fail("fmi3InstantiateCoSimulation returned NULL");
    return c;
}

void initialize(fmi3Instance c)
{
    check(fmu.EnterInitializationMode(c, fmi3False, 0.0, 0.0, fmi3False, 0.0), "EnterInit");
    check(fmu.ExitInitializationMode(c), "ExitInitializationMode");
}

fmi3Status step(fmi3Instance c, double time, double h)
{
    fmi3Boolean event, terminate, early;
    fmi3Float64 last;
    return fmu.DoStep(c, time, h, fmi3True, &event, &terminate, &early, &last);
}

/* All outputs, FMPy's communication points start + k * dt; `out` gets the CSV. */
void simulate(FILE *out, int steps, double dt, int n_settings, char **settings)
{
    fmi3Instance c = start("run");
    for (int i = 0; i < n_settings; i++) {
        char name[64];
        double value;
        if (sscanf(settings[i], "%63[^=]=%lf", name, &value) != 2)
            fail("expected name=value, got %s", settings[i]);
        check(fmu.SetFloat64(c, &variable(name)->vr, 1, &value, 1), "SetFloat64");
    }
    initialize(c);
    fmi3ValueReference vr[64];
    size_t n = 0, n_values = 0;
    fprintf(out, "\"time\"");
    for (int i = 0; i < fmu.n_variables; i++) {
        const struct variable *v = &fmu.variables[i];
        if (strcmp(v->causality, "output") != 0)
            continue;
        vr[n++] = v->vr;
        n_values += (size_t)v->size;
        for (int k = 0; k < v->size; k++)
            v->size > 1 ? fprintf(out, ",\"%s[%d]\"", v->name, k + 1)
                        : fprintf(out, ",\"%s\"", v->name);
    }
    fprintf(out, "\n");
    double time = 0.0, y[256];
    for (int k = 0; k <= steps; k++) {
        check(fmu.GetFloat64(c, vr, n, y, n_values), "GetFloat64");
        fprintf(out, "%.17g", time);
        for (size_t i = 0; i < n_values; i++)
            fprintf(out, ",%.17g", y[i]);
        fprintf(out, "\n");
        if (k == steps)
            break;
        double next = (k + 1) * dt;
        check(step(c, time, next - time), "DoStep");
        time = next;
    }
    check(fmu.Terminate(c), "Terminate");
    fmu.FreeInstance(c);
}

static int bad(const char *name, double value)
{
    fmi3Instance c = start("bad");
    initialize(c);
    int before = log_calls;
    fmi3Status set = fmu.SetFloat64(c, &variable(name)->vr, 1, &value, 1);
    fmi3Status stepped = step(c, 0.0, 1e-3);
    printf("set %d step %d logger_calls %d\nmessage %s\n", set, stepped, log_calls - before,
           last_message);
    fmu.FreeInstance(c);
    return 0;
}

static int instantiate_only(void)
{
    fmi3Instance c = instantiate("probe", fmi3False);
    printf("instance %s logger_calls %d\n", c ? "ok" : "NULL", log_calls);
    if (c)
        fmu.FreeInstance(c);
    return 0;
}

/* Each call prints "<what> <status> <logger calls> | <last message>". */
static void answer(const char *what, fmi3Status status, int *before)
{
    printf("%s %d %d | %s\n", what, status, log_calls - *before, last_message);
    *before = log_calls;
    last_message[0] = '\0';
}

static int misuse(void)
{
    int n = log_calls;
    answer("model_exchange", fmu.InstantiateModelExchange("me", fmu.token, fmu.resources,
           fmi3False, fmi3False, NULL, logger) ? fmi3OK : fmi3Error, &n);
    fmi3Instance c = start("misuse");
    fmi3ValueReference speed = variable("input_speed")->vr;
    fmi3ValueReference pair[] = {speed, variable("crosspiece_quaternion")->vr}, unknown = 999;
    double values[8] = {0};
    float single;
    answer("step_before_init", step(c, 0.0, 1e-3), &n);
    answer("exit_before_enter", fmu.ExitInitializationMode(c), &n);
    initialize(c);
    answer("enter_twice", fmu.EnterInitializationMode(c, fmi3False, 0, 0, fmi3False, 0), &n);
    answer("get_float32", fmu.GetFloat32(c, &speed, 1, &single, 1), &n);
    answer("get_float32_none", fmu.GetFloat32(c, NULL, 0, NULL, 0), &n);
    answer("get_clock", fmu.GetClock(c, &speed, 1, NULL), &n);
    answer("event_mode", fmu.EnterEventMode(c), &n);
    fmi3Boolean flags[5];
    fmi3Float64 next_time;
    answer("update_discrete", fmu.UpdateDiscreteStates(c, flags, flags + 1, flags + 2, flags + 3,
                                                       flags + 4, &next_time), &n);
    answer("directional", fmu.GetDirectionalDerivative(c, &speed, 1, &speed, 1, values, 1,
                                                       values, 1), &n);
    answer("short_count", fmu.GetFloat64(c, pair, 2, values, 4), &n);
    answer("long_count", fmu.GetFloat64(c, pair, 2, values, 6), &n);
    answer("unknown_reference", fmu.GetFloat64(c, &unknown, 1, values, 1), &n);
    answer("null_values", fmu.GetFloat64(c, pair, 2, NULL, 5), &n);
    answer("right_count", fmu.GetFloat64(c, pair, 2, values, 5), &n);
    answer("step_null_results", fmu.DoStep(c, 0.0, 1e-3, fmi3True, NULL, NULL, NULL, NULL), &n);
    answer("step", step(c, 0.0, 1e-3), &n);
    fmi3FMUState state = NULL, foreign = &n, freed;
    static char bytes[1 << 16];
    size_t size = 0;
    answer("get_state", fmu.GetFMUState(c, &state), &n);
    answer("set_foreign_state", fmu.SetFMUState(c, foreign), &n);
    check(fmu.SerializedFMUStateSize(c, state, &size), "SerializedFMUStateSize");
    answer("serialize_short", fmu.SerializeFMUState(c, state, bytes, size - 1), &n);
    answer("serialize_long", fmu.SerializeFMUState(c, state, bytes, sizeof bytes), &n);
    freed = state;
    answer("free_state", fmu.FreeFMUState(c, &state), &n);
    answer("set_freed_state", fmu.SetFMUState(c, freed), &n);
    answer("free_again", fmu.FreeFMUState(c, &freed), &n);
    check(fmu.Terminate(c), "Terminate");
    answer("step_after_terminate", step(c, 1e-3, 1e-3), &n);
    answer("reset", fmu.Reset(c), &n);
    initialize(c);
    answer("step_after_reset", step(c, 0.0, 1e-3), &n);
    fmu.FreeInstance(c);
    return 0;
}

static int cycles(int n)
{
    for (int i = 0; i < n; i++) {
        fmi3Instance c = start("cycle");
        initialize(c);
        for (int k = 0; k < 5; k++)
            check(step(c, k * 1e-3, 1e-3), "DoStep");
        check(fmu.Terminate(c), "Terminate");
        fmu.FreeInstance(c);
    }
    printf("cycles %d ok\n", n);
    return 0;
}

int main(int argc, char **argv)
{
    setvbuf(stdout, NULL, _IOFBF, 1 << 16);
    if (argc < 3) {
        fprintf(stderr, "usage: see the comment at the top of host3.c\n");
        return 2;
    }
    load(argv[2]);
    if (argc >= 5 && strcmp(argv[1], "run") == 0)
        return simulate(stdout, atoi(argv[3]), atof(argv[4]), argc - 5, argv + 5), 0;
    if (argc == 5 && strcmp(argv[1], "bad") == 0)
        return bad(argv[3], strtod(argv[4], NULL));
    if (argc == 5 && strcmp(argv[1], "refusal") == 0)
        return refusal3(argv[3], strtod(argv[4], NULL));
    if (argc == 3 && strcmp(argv[1], "instantiate") == 0)
        return instantiate_only();
    if (argc == 3 && strcmp(argv[1], "misuse") == 0)
        return misuse();
    if (argc == 4 && strcmp(argv[1], "threads") == 0)
        return threads3(atoi(argv[3]));
    if (argc == 4 && strcmp(argv[1], "cycles") == 0)
        return cycles(atoi(argv[3]));
    if (argc == 5 && strcmp(argv[1], "fuzz") == 0)
        return fuzz3(strtoul(argv[3], NULL, 10), atoi(argv[4]));
    fprintf(stderr, "usage: see the comment at the top of host3.c\n");
    return 2;
}
