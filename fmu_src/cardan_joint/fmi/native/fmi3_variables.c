/* Each FMI 3.0 variable's value reference, type and size, from the record the
 * build writes (resources/VARIABLES_RECORD, see native/__init__.py): the
 * loader checks value references and value counts against it.  Hosts need not
 * extract modelDescription.xml (FMPy extracts resources/ and binaries/ only). */
#include "fmi3_instance.h"

#include <stdio.h>
#include <string.h>

const char *const TYPE_NAMES[N_TYPES] = {
    "Float32", "Float64", "Int8",  "UInt8",   "Int16",  "UInt16", "Int32",
    "UInt32",  "Int64",   "UInt64", "Boolean", "String", "Binary", "Clock"};

static int type_of(const char *name)
{
    for (int t = 0; t < N_TYPES; t++)
        if (strcmp(name, TYPE_NAMES[t]) == 0)
            return t;
    return -1;
}

static int keep_variable(const struct record_row *row, void *kept)
{
    struct variables *variables = kept;
    int type = type_of(row->type);
    if (type < 0 || variables->count >= MAX_VARIABLES)
        return 0;
    struct variable *v = &variables->list[variables->count++];
    v->vr = row->vr;
    v->type = (enum value_type)type;
    v->size = row->size;
    v->fixed = row->fixed;
    snprintf(v->name, sizeof v->name, "%s", row->name);
    return 1;
}

int read_variables(const char *resources, struct variables *variables, char *error, size_t size)
{
    variables->count = 0;
    return read_variable_record(resources, keep_variable, variables, MAX_VARIABLES, error, size);
}

const struct variable *find_variable(const struct variables *variables, fmi3ValueReference vr)
{
    for (int i = 0; i < variables->count; i++)
        if (variables->list[i].vr == vr)
            return &variables->list[i];
    return NULL;
}
