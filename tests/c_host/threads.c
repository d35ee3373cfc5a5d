/* Threads: each its own instance at once, then one instance from two threads in
 * turn; every result must equal the same run on the main thread, bit for bit. */
#include "host.h"

#include <pthread.h>
#include <string.h>

struct job {
    fmi2Component c;
    double speed;
    int first, count;
    double result[64];
};

static void steps(struct job *job)
{
    fmi2ValueReference speed = reference("input_speed"), out[64];
    int n = outputs(out);
    for (int k = job->first; k < job->first + job->count; k++) {
        check(fmu.SetReal(job->c, &speed, 1, &job->speed), "SetReal");
        check(fmu.DoStep(job->c, k * 1e-3, 1e-3, fmi2True), "DoStep");
    }
    check(fmu.GetReal(job->c, out, n, job->result), "GetReal");
}

static void *in_thread(void *job)
{
    steps(job);
    return NULL;
}

static void on_new_thread(struct job *job)
{
    pthread_t thread;
    pthread_create(&thread, NULL, in_thread, job);
    pthread_join(thread, NULL);
}

static void serial(struct job *job, double speed, int count)
{
    *job = (struct job){start("serial", fmi2False), speed, 0, count, {0}};
    initialize(job->c);
    steps(job);
    fmu.FreeInstance(job->c);
}

static int same(const char *what, const struct job *a, const struct job *b)
{
    fmi2ValueReference out[64];
    if (memcmp(a->result, b->result, outputs(out) * sizeof(double)) == 0)
        return 1;
    printf("%s differs from the serial run\n", what);
    return 0;
}

int threads(const char *dir, int count)
{
    load(dir);
    struct job reference_a, reference_b, a, b;
    serial(&reference_a, 10.0, count);
    serial(&reference_b, 25.0, count);

    a = (struct job){start("a", fmi2False), 10.0, 0, count, {0}};
    b = (struct job){start("b", fmi2False), 25.0, 0, count, {0}};
    initialize(a.c);
    initialize(b.c);
    pthread_t ta, tb;
    pthread_create(&ta, NULL, in_thread, &a);
    pthread_create(&tb, NULL, in_thread, &b);
    pthread_join(ta, NULL);
    pthread_join(tb, NULL);
    int ok = same("thread a", &a, &reference_a) & same("thread b", &b, &reference_b);
    fmu.FreeInstance(a.c);
    fmu.FreeInstance(b.c);

    struct job shared = {start("shared", fmi2False), 10.0, 0, count / 2, {0}};
    initialize(shared.c);
    on_new_thread(&shared);                     /* first half on one thread ... */
    shared.first = count / 2;
    shared.count = count - count / 2;
    on_new_thread(&shared);                     /* ... the rest on another */
    ok &= same("one instance on two threads", &shared, &reference_a);
    fmu.FreeInstance(shared.c);
    printf("threads %s\n", ok ? "ok" : "FAILED");
    return ok ? 0 : 1;
}
