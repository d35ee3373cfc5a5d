/* Two FMI 3.0 instances on two host threads give what one gives alone: each
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
    printf("threads ok (%zu bytes each)\n", alone.size);
    return 0;
}
