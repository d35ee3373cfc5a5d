/* The fast path's layout and value references (the protocol:
 * fmi/fast_path.py): the counts the slave gives, checked before any array is
 * sized from them; the table of each reference's flat indices, whether the
 * arrays serve a call's references, and the flat indices a getReal reads, for
 * the slave's fast_outputs. */
#include "fast_path.h"
#include "python_api.h"

#include <stdlib.h>
#include <string.h>

/* More values of a kind than any model has: the arrays' sizes and the replies'
 * counts are sums and products of these, which must not overflow. */
#define MOST_VALUES (1L << 20)

int sizes_taken(struct instance *in, const struct fast_path *fast)
{
    int taken = 0 < fast->inputs && fast->inputs <= fast->known_size &&
                fast->known_size <= MOST_VALUES && fast->known_size == fast->first_output &&
                0 < fast->outputs && fast->outputs <= MOST_VALUES && 0 <= fast->state_size &&
                fast->state_size <= MOST_VALUES;
    if (!taken)
        reportf(in, fmi2Warning, "the slave's layout (%ld inputs, %ld known values, %ld "
                "outputs, a step state of %ld) is beyond what the runtime's arrays take (1 to "
                "%ld of each, a state of 0 to %ld): its values go through plain calls",
                fast->inputs, fast->known_size, fast->outputs, fast->state_size, MOST_VALUES,
                MOST_VALUES);
    return taken;
}

/* Each reference's SERVES_* flags and single index, from a table fast_table
 * has checked. */
static int flag_references(struct fast_path *fast)
{
    long long refs = fast->table[0];
    fast->serves = malloc((size_t)refs);
    fast->single = malloc((size_t)refs * sizeof *fast->single);
    if (!fast->serves || !fast->single)
        return 0;
    for (long long vr = 0; vr < refs; vr++) {
        const long long *indices;
        long long count = flat_of(fast, (unsigned)vr, &indices);
        unsigned char flags = count > 0 ? SERVES_VALUE | SERVES_INPUT : 0;
        for (long long k = 0; k < count; k++)
            if (indices[k] >= fast->inputs)
                flags &= (unsigned char)~SERVES_INPUT;
        fast->serves[vr] = flags;
        fast->single[vr] = count == 1 ? indices[0] : -1;
    }
    return 1;
}

/* Takes the table of the slave's value references; 0 if there is none or it
 * is malformed: each reference's start from 0 up, never past the indices, and
 * every index within the arrays (flat_of reads them all unchecked). */
int fast_table(struct fast_path *fast, const char *bytes, size_t size)
{
    free(fast->table);
    free(fast->serves);
    free(fast->single);
    fast->table = NULL;
    fast->serves = NULL;
    fast->single = NULL;
    long long n = (long long)(size / 8), limit = fast->first_output + fast->outputs;
    if (size == 0 || size % 8 || !(fast->table = malloc(size)))
        return 0;
    memcpy(fast->table, bytes, size);
    long long refs = fast->table[0];
    int ok = refs >= 1 && n >= refs + 2 && fast->table[refs + 1] == n - refs - 2 &&
             fast->table[1] == 0;
    for (long long vr = 1; ok && vr <= refs; vr++)
        ok = fast->table[vr] <= fast->table[vr + 1];
    for (long long i = refs + 2; ok && i < n; i++)
        ok = fast->table[i] >= 0 && fast->table[i] < limit;
    return ok && flag_references(fast);
}

int fast_serves(const struct instance *in, const unsigned vr[], size_t n, int inputs_only)
{
    const struct fast_path *fast = in->fast;
    if (!fast)
        return 0;
    unsigned long long references = (unsigned long long)fast->table[0];
    unsigned char needed = inputs_only ? SERVES_INPUT : SERVES_VALUE;
    for (size_t i = 0; i < n; i++)
        if (vr[i] >= references || !(fast->serves[vr[i]] & needed))
            return 0;
    return 1;
}

PyObject *read_indices(const struct fast_path *fast)
{
    long long total = 0;
    const long long *indices;
    for (size_t i = 0; i < fast->reading_count; i++)
        total += flat_of(fast, fast->reading[i], &indices);
    PyObject *tuple = p_PyTuple_New((Py_ssize_t)total);
    Py_ssize_t at = 0;
    for (size_t i = 0; tuple && i < fast->reading_count; i++) {
        long long count = flat_of(fast, fast->reading[i], &indices);
        for (long long k = 0; tuple && k < count; k++) {
            PyObject *item = p_PyLong_FromLong((long)indices[k]);
            if (!item || p_PyTuple_SetItem(tuple, at++, item)) {
                p_Py_DecRef(tuple);
                tuple = NULL;
            }
        }
    }
    return tuple;
}
