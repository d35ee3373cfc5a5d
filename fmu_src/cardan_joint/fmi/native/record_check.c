/* The build's variable record (resources/VARIABLES_RECORD) against the slave's
 * own layout, at instantiate: the record sizes FMI 3.0's value counts and
 * names the fixed parameters, so a record that disagrees with what the slave
 * writes (damaged, truncated, from another build) would let a host's buffer be
 * overrun or a guard fall silent.  The slave's layout is the fast path's
 * (fast_path.c): every Real/Float64 row must hold exactly the flat indices the
 * slave gives its value reference, the rows together every flat index once,
 * and a fixed row only parameters; every row is a real, as the slave's are.
 * An instance without the fast path
 * (the benchmarks' floor FMU) has no layout to check against. */
#define _GNU_SOURCE
#include "fast_path.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

struct check {
    const struct fast_path *fast;
    unsigned char *seen;  /* per flat index: rows that hold it */
    long long limit;      /* flat indices: inputs, parameters, outputs */
    int timed;            /* rows that held FMI 3.0's time */
    char problem[256];
};

static int fail(struct check *check, const struct record_row *row, const char *what)
{
    snprintf(check->problem, sizeof check->problem, "variable %s (value reference %u) %s",
             row->name, row->vr, what);
    return 0;
}

static int check_row(const struct record_row *row, void *data)
{
    struct check *check = data;
    /* The slave's layout holds reals only: a row of another type is not the slave's
     * (a model with integer variables would extend the layout first). */
    if (strcmp(row->type, "Real") != 0 && strcmp(row->type, "Float64") != 0)
        return fail(check, row, "has a type the slave does not have");
    const long long *indices;
    long long count = flat_of(check->fast, row->vr, &indices);
    /* FMI 3.0's time, once: one value, no flat index, a value reference the slave
     * has (0 is none: value references are 1-based positions, fmi/references.py). */
    if (count == 0)
        return row->vr > 0 &&
                       row->vr < (unsigned long long)check->fast->table[0] && row->size == 1 &&
                       !check->timed++
                   ? 1
                   : fail(check, row, "is not the slave's");
    if ((unsigned long long)count != row->size)
        return fail(check, row, "has another size than the slave's");
    for (long long k = 0; k < count; k++) {
        long long i = indices[k];
        if (i < 0 || i >= check->limit || check->seen[i]++)
            return fail(check, row, "is not the slave's, or named twice");
        if (row->fixed && (i < check->fast->inputs || i >= check->fast->known_size))
            return fail(check, row, "is fixed but not a parameter of the slave");
    }
    return 1;
}

int record_matches_slave(struct instance *in, const char *resources, char *error, size_t size)
{
    struct check check = {.fast = in->fast};
    if (!in->fast)
        return 0;
    check.limit = in->fast->first_output + in->fast->outputs;
    if (!(check.seen = calloc((size_t)check.limit, 1))) {
        snprintf(error, size, "out of memory");
        return -1;
    }
    char reading[1024];
    int result = read_variable_record(resources, check_row, &check, 1 << 20, reading,
                                      sizeof reading);
    for (long long i = 0; result == 0 && !check.problem[0] && i < check.limit; i++)
        if (!check.seen[i])
            snprintf(check.problem, sizeof check.problem,
                     "holds no variable of the slave's flat index %lld", i);
    free(check.seen);
    if (result == 0 && !check.problem[0])
        return 0;
    if (check.problem[0])
        snprintf(error, size, "%s/" VARIABLES_RECORD " contradicts the slave: %s; the FMU is "
                 "damaged, rebuild it", resources, check.problem);
    else
        snprintf(error, size, "%s", reading);
    return -1;
}
