/* Each FMI 3.0 variable's value reference, type and size, from the record the
 * build writes (resources/VARIABLES_RECORD, see native/__init__.py): the
 * loader checks value references and value counts against it.  Hosts need not
 * extract modelDescription.xml (FMPy extracts resources/ and binaries/ only). */
#include "fmi3_instance.h"

#include <errno.h>
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

int read_variables(const char *resources, struct variables *variables, char *error, size_t size)
{
    char name[4200], line[256], type[16];
    snprintf(name, sizeof name, "%s/" VARIABLES_RECORD, resources);
    FILE *file = fopen(name, "r");
    if (!file) {
        snprintf(error, size, "cannot read %s (%s): the FMU is incomplete, rebuild it", name,
                 strerror(errno));
        return -1;
    }
    variables->count = 0;
    int line_number = 0, ok = 1;
    while (ok && fgets(line, sizeof line, file)) {
        line_number++;
        if (line[0] == '#' || line[0] == '\n')
            continue;
        struct variable *v = &variables->list[variables->count];
        ok = variables->count < MAX_VARIABLES &&
             sscanf(line, "%u %15s %zu %d %63s", &v->vr, type, &v->size, &v->fixed, v->name) == 5 &&
             type_of(type) >= 0;
        if (ok) {
            v->type = (enum value_type)type_of(type);
            variables->count++;
        }
    }
    fclose(file);
    if (!ok)
        snprintf(error, size, "%s, line %d: not 'valueReference type size fixed name' "
                              "(at most %d variables): rebuild the FMU", name, line_number,
                 MAX_VARIABLES);
    return ok ? 0 : -1;
}

const struct variable *find_variable(const struct variables *variables, fmi3ValueReference vr)
{
    for (int i = 0; i < variables->count; i++)
        if (variables->list[i].vr == vr)
            return &variables->list[i];
    return NULL;
}
