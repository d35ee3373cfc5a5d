/* One FMI 3.0 instance as the runtime sees it.  The FMI 3.0 types and
 * prototypes come from the standard's headers, which pythonfmu3 ships (the
 * build adds their folder to the include path). */
#ifndef CARDAN_JOINT_FMI3_INSTANCE_H
#define CARDAN_JOINT_FMI3_INSTANCE_H

#include "fmi3Functions.h"
#include "instance.h"

/* The accessor a variable's values go through (Enumeration: Int64). */
enum value_type {
    T_FLOAT32, T_FLOAT64, T_INT8, T_UINT8, T_INT16, T_UINT16, T_INT32, T_UINT32, T_INT64,
    T_UINT64, T_BOOLEAN, T_STRING, T_BINARY, T_CLOCK, N_TYPES
};
extern const char *const TYPE_NAMES[N_TYPES];

#define MAX_VARIABLES 256
struct variables {
    struct variable {
        fmi3ValueReference vr;
        enum value_type type;
        size_t size;          /* product of its <Dimension start=...>: values it takes */
        int fixed;            /* variability fixed or constant */
        char name[64];
    } list[MAX_VARIABLES];
    int count;
};
/* From resources/VARIABLES_RECORD; -1 and a message if unreadable. */
int read_variables(const char *resources, struct variables *variables, char *error, size_t size);
const struct variable *find_variable(const struct variables *variables, fmi3ValueReference vr);

struct instance3 {
    struct instance base;          /* first: enter() and report() work on it */
    fmi3InstanceEnvironment environment;
    fmi3LogMessageCallback log_message;
    const struct variables *variables;
};

/* Values of `type` for `vr`: known references of that type, as many values as
 * they hold, arrays given; else fmi3Error logged and 0. */
int values_fit(struct instance3 *in, const char *function, enum value_type type,
               const fmi3ValueReference vr[], size_t nvr, const void *values, size_t n_values,
               int setting);
fmi3Status unsupported3(fmi3Instance instance, unsigned allowed, const char *function,
                        const char *why);

#endif
