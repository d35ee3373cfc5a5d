/* Two FMI 3.0 instances on two host threads at once, then one instance driven
 * from two threads in turn, give what one gives alone on one thread: each host
 * thread gets its own Python thread state from the loader. */
#include "host3.h"

#include <pthread.h>
#include <stdio.h>
#include <string.h>

struct job {
    int steps;
    char *csv;
    size_t size;
};

static void *simulate_job(void *argument)
{
    struct job *job = argument;
    char settings[] = "bend_angle=0.4", *list[] = {settings};
    FILE *out = open_memstream(&job->csv, &job->size);
    simulate(out, job->steps, 1e-3, 1, list);
    fclose(out);
    return NULL;
}

struct turn {
    fmi3Instance c;
    int first, count;
};

static void *steps_in_thread(void *argument)
{
    struct turn *turn = argument;
    for (int k = turn->first; k < turn->first + turn->count; k++)  /* as simulate() */
        check(step(turn->c, k * 1e-3, (k + 1) * 1e-3 - k * 1e-3), "DoStep");
    return NULL;
}

/* The outputs after `steps` steps, taken by two threads in turn: a CSV line. */
static char *in_turns(int steps)
{
    fmi3ValueReference out[64];
    double y[256];
    size_t n = 0, n_values = 0;
    for (int i = 0; i < fmu.n_variables; i++)
        if (strcmp(fmu.variables[i].causality, "output") == 0) {
            out[n++] = fmu.variables[i].vr;
            n_values += (size_t)fmu.variables[i].size;
        }
    fmi3Instance c = start("turns");
    fmi3ValueReference bend = variable("bend_angle")->vr;
    double angle = 0.4;
    check(fmu.SetFloat64(c, &bend, 1, &angle, 1), "SetFloat64");
    initialize(c);
    struct turn turns[2] = {{c, 0, steps / 2}, {c, steps / 2, steps - steps / 2}};
    for (int i = 0; i < 2; i++) {
        pthread_t thread;
        pthread_create(&thread, NULL, steps_in_thread, &turns[i]);
        pthread_join(thread, NULL);
    }
    check(fmu.GetFloat64(c, out, n, y, n_values), "GetFloat64");
    fmu.FreeInstance(c);
    static char line[8192];
    size_t used = 0;
    for (size_t i = 0; i < n_values; i++)
        used += (size_t)snprintf(line + used, sizeof line - used, ",%.17g", y[i]);
    return line;
}

int threads3(int steps)
{
    struct job alone = {steps, NULL, 0}, jobs[2] = {{steps, NULL, 0}, {steps, NULL, 0}};
    simulate_job(&alone);
    pthread_t id[2];
    for (int i = 0; i < 2; i++)
        pthread_create(&id[i], NULL, simulate_job, &jobs[i]);
    for (int i = 0; i < 2; i++)
        pthread_join(id[i], NULL);
    for (int i = 0; i < 2; i++)
        if (strcmp(jobs[i].csv, alone.csv) != 0)
            fail("thread %d differs from the run alone", i);
    const char *last = strrchr(alone.csv, '\n'), *end = last;
    while (last > alone.csv && last[-1] != '\n')
        last--;
    last = strchr(last, ',');  /* the last row's outputs, after its time */
    const char *turns = in_turns(steps);
    if (strlen(turns) != (size_t)(end - last) || strncmp(turns, last, strlen(turns)) != 0)
        fail("one instance on two threads in turn differs from the run alone");
    printf("threads ok (%zu bytes each)\n", alone.size);
    return 0;
}
