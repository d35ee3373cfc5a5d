/* One FMU instance as the runtime sees it. */
#ifndef CARDAN_JOINT_INSTANCE_H
#define CARDAN_JOINT_INSTANCE_H

#include "fmi2.h"
#include "loader.h"

#ifndef MODEL_IDENTIFIER
#error "compile with -DMODEL_IDENTIFIER=\"<modelIdentifier>\""
#endif

#define INSTANCE_MAGIC 0x4341524aU

/* FMI 2.0 co-simulation states; a mask of them says where a call is legal. */
enum state {
    STATE_INSTANTIATED = 1,
    STATE_INITIALIZATION = 2,
    STATE_STEP_COMPLETE = 4,
    STATE_TERMINATED = 8,
    STATE_FATAL = 16,
};

#define ALIVE (STATE_INSTANTIATED | STATE_INITIALIZATION | STATE_STEP_COMPLETE | STATE_TERMINATED)
#define ANY (ALIVE | STATE_FATAL)

typedef struct _object PyObject;

struct instance {
    unsigned magic;
    void *slave;                     /* FMI 3.0: pythonfmu3's instance */
    PyObject *object;                /* FMI 2.0: the slave's Python object (slave_object.c) */
    PyObject *strings;               /* FMI 2.0: the last fmi2GetString's values, kept alive */
    double start, stop, tolerance;   /* FMI 2.0: the experiment, for enter initialization */
    int stop_defined, tolerance_defined;
    double last_successful_time;     /* fmi2LastSuccessfulTime: NaN before any step */
    const char *model;
    char *name, *guid, *resources_uri;
    char *resources;                 /* FMI 2.0: the resources folder, for reset */
    fmi2Boolean visible;
    fmi2CallbackFunctions host;      /* the host's callbacks, as given */
    int logging_on, echo_stderr, shared_proxy;
    char **categories;
    size_t n_categories;
    enum state state;
    fmi2Status worst;                /* worst status logged during the current call */
    const struct fixed_parameters *fixed;
    fmi2FMUstate *fmu_states;        /* the live FMU states this instance handed out */
    size_t n_fmu_states, fmu_states_capacity;
    struct fast_path *fast;          /* the one-call step's arrays; NULL: plain forwarding */
};

int load_slave_library(const char *suffix, int (*resolve)(void *, char *, size_t), char *error,
                       size_t size);
/* Per FMI version: the host's logger (0: the host has none) and what a call
 * in `state` should have been preceded by. */
int to_host(const struct instance *in, fmi2Status status, const char *category, const char *text);
const char *where(enum state state);
int is_shared_proxy(void *logger);
/* Every fmi2 call on an instance: enter() checks it and the state machine
 * (NULL: answer fmi2Error), leave() returns the worst status logged. */
struct instance *enter(fmi2Component c, unsigned allowed, const char *function);
fmi2Status leave(struct instance *in, fmi2Status status);
fmi2Status step_status(struct instance *in, fmi2Status status);
int arrays_given(struct instance *in, const char *function, size_t n, const void *references,
                 const void *values);
fmi2Status set_debug_logging(struct instance *in, const char *function, int on, size_t n,
                             const char *const categories[]);
/* FMU states this instance handed out (state_book.c); free_slave_state is the
 * slave's own free, per FMI version. */
int known_state(struct instance *in, fmi2FMUstate state, const char *function);
void keep_state(struct instance *in, fmi2FMUstate state);
int prepare_new_state(struct instance *in, fmi2FMUstate *state, const char *function);
fmi2Status drop_state(struct instance *in, fmi2FMUstate *state);
fmi2Status free_slave_state(struct instance *in, fmi2FMUstate *state);
/* The one-call step (fast_path.c): set up after instantiate (NULL when the slave
 * cannot take it), re-found after reset; fast_before/fast_after go around every
 * other call into the slave; fast_serves says whether fast_set (inputs_only) or
 * fast_get can answer these value references in C. */
void fast_attach(struct instance *in, const char *resources);
void fast_detach(struct instance *in);
void fast_reset(struct instance *in);
void fast_before(struct instance *in);
void fast_after(struct instance *in);
int fast_serves(const struct instance *in, const unsigned vr[], size_t n, int inputs_only);
void fast_set(struct instance *in, const unsigned vr[], size_t n, const double value[]);
fmi2Status fast_get(struct instance *in, const unsigned vr[], size_t n, double value[]);
int fast_step(struct instance *in, double time, double step);
int fast_initialized(struct instance *in);
/* After a set FMU state: the mode the state was taken in (calls.c). */
void restore_mode(struct instance *in, fmi2Status status);
char *copy_of(const char *text);  /* strdup, "" for NULL */
/* The script module pythonfmu imports (resources/slavemodule.txt) imports in
 * this process's Python; else -1 and the Python error. */
int slave_module_imports(const char *resources, char *error, size_t size);
/* resources/VARIABLES_RECORD agrees with the slave's own layout (the one-call
 * step's): else -1 and a message naming the file (record_check.c). */
int record_matches_slave(struct instance *in, const char *resources, char *error, size_t size);
/* FMI 2.0: the slave's Python object and its calls (slave_object.c). */
int slave_construct(struct instance *in, const char *resources);
void slave_release(struct instance *in);
void slave_drain(struct instance *in, PyObject *slave);
fmi2Status slave_call(struct instance *in, const char *method);
fmi2Status slave_do_step(struct instance *in, double time, double step);
fmi2Status slave_get(struct instance *in, const char *method, char kind, const unsigned vr[],
                     size_t n, void *value);
fmi2Status slave_set(struct instance *in, const char *method, char kind, const unsigned vr[],
                     size_t n, const void *value);
fmi2Status slave_get_state(struct instance *in, fmi2FMUstate *state);
fmi2Status slave_set_state(struct instance *in, fmi2FMUstate state);
fmi2Status slave_free_state(fmi2FMUstate *state);
fmi2Status slave_state_bytes(struct instance *in, fmi2FMUstate state, char *bytes, size_t *size);
fmi2Status slave_state_from_bytes(struct instance *in, const char *bytes, size_t size,
                                  fmi2FMUstate *state);
void free_instance(struct instance *in);
void release_instance(struct instance *in, void (*free_slave)(void *));
void report(struct instance *in, fmi2Status status, const char *category, const char *text);
void reportf(struct instance *in, fmi2Status status, const char *format, ...)
    __attribute__((format(printf, 3, 4)));

#endif
