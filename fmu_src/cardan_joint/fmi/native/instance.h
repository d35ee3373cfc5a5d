/* One FMU instance as the runtime sees it. */
#ifndef CARDAN_JOINT_INSTANCE_H
#define CARDAN_JOINT_INSTANCE_H

#include "fmi2.h"
#include "loader.h"

#ifndef MODEL_IDENTIFIER
#error "compile with -DMODEL_IDENTIFIER=\"<modelIdentifier>\""
#endif

#define INSTANCE_MAGIC 0x4341524aU

/* The co-simulation states of FMI 2.0 and 3.0 (no event mode); a mask of them
 * says where a call is legal. */
enum state {
    STATE_INSTANTIATED = 1,
    STATE_INITIALIZATION = 2,
    STATE_STEP_COMPLETE = 4,
    STATE_TERMINATED = 8,
    STATE_FATAL = 16,
    /* The slave lost track of the instance (it could not take the steps taken
     * in C): only reset and free, as FMI asks after an error. */
    STATE_ERROR = 32,
};

#include "masks.h"

typedef struct _object PyObject;

struct instance {
    unsigned magic;
    PyObject *object;                /* the slave's Python object (slave_object.c) */
    PyObject *strings;               /* the last string getter's values, kept alive */
    double start, stop, tolerance;   /* FMI 2.0: the experiment, for enter initialization */
    int stop_defined, tolerance_defined;
    double last_successful_time;     /* fmi2LastSuccessfulTime: NaN before any step */
    const char *model;
    char *name, *guid, *resources_uri;
    char *resources;                 /* the resources folder, for reset */
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
    struct fast_path *fast;          /* the fast path's arrays; NULL: plain forwarding */
};

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
/* FMU states this instance handed out (state_book.c). */
int known_state(struct instance *in, fmi2FMUstate state, const char *function);
void keep_state(struct instance *in, fmi2FMUstate state);
int prepare_new_state(struct instance *in, fmi2FMUstate *state, const char *function);
fmi2Status drop_state(struct instance *in, fmi2FMUstate *state);
/* The FMU state calls, each named by its FMI function (state_book.c). */
fmi2Status state_get(void *c, fmi2FMUstate *state, unsigned allowed, const char *function);
fmi2Status state_set(void *c, fmi2FMUstate state, unsigned allowed, const char *function);
fmi2Status state_free(void *c, fmi2FMUstate *state, unsigned allowed, const char *function);
fmi2Status state_size(void *c, fmi2FMUstate state, size_t *size, unsigned allowed,
                      const char *function);
fmi2Status state_serialize(void *c, fmi2FMUstate state, char bytes[], size_t size,
                           unsigned allowed, const char *function);
fmi2Status state_deserialize(void *c, const char bytes[], size_t size, fmi2FMUstate *state,
                             unsigned allowed, const char *function);
/* The fast path (fast_path.c): set up after instantiate (NULL when the slave
 * cannot take it), re-found after reset; fast_before/fast_after go around every
 * call into the slave (fast_before: -1 when the slave could not catch up,
 * the instance then in STATE_ERROR: the call must not reach it; fast_after:
 * the status of the slave's store); fast_serves says whether fast_set
 * (inputs_only) or fast_get can answer these value references in C; fast_step
 * is every doStep, through the generated step or the slave's do_step (in one
 * call of its fast_do_step, which takes the inputs and stores itself). */
void fast_attach(struct instance *in);
void fast_detach(struct instance *in);
void fast_reset(struct instance *in);
int fast_before(struct instance *in);
long fast_after(struct instance *in);
int fast_serves(const struct instance *in, const unsigned vr[], size_t n, int inputs_only);
void fast_set(struct instance *in, const unsigned vr[], size_t n, const double value[]);
fmi2Status fast_get(struct instance *in, const unsigned vr[], size_t n, double value[]);
fmi2Status fast_step(struct instance *in, double time, double step, int *terminate);
/* After a set FMU state: the mode the state was taken in (calls.c). */
void restore_mode(struct instance *in, fmi2Status status);
fmi2Status reset_slave(struct instance *in);
fmi2Status transition(void *c, unsigned allowed, const char *function,
                      fmi2Status (*first)(struct instance *), const char *method, enum state next);
char *copy_of(const char *text);  /* strdup, "" for NULL */
/* The script module pythonfmu imports (resources/slavemodule.txt) imports in
 * this process's Python; else -1 and the Python error. */
int slave_module_imports(const char *resources, char *error, size_t size);
/* resources/VARIABLES_RECORD agrees with the slave's own layout (the fast
 * path's): else -1 and a message naming the file (record_check.c). */
int record_matches_slave(struct instance *in, const char *resources, char *error, size_t size);
/* The slave's Python object and its calls (slave_object.c, slave_values.c), for
 * both FMI versions; SLAVE_BASE names the slave class's base (per FMI version). */
extern const char SLAVE_BASE[];
int slave_construct(struct instance *in, const char *resources);
void slave_release(struct instance *in);
void slave_drain(struct instance *in, PyObject *slave);
fmi2Status slave_call(struct instance *in, const char *method);
fmi2Status slave_setup_experiment(struct instance *in);
fmi2Status slave_do_step(struct instance *in, double time, double step, int *terminate);
int slave_initialized(struct instance *in);
/* n value references, n_values values (FMI 2.0: as many as references). */
fmi2Status slave_get(struct instance *in, const char *method, char kind, const unsigned vr[],
                     size_t n, void *value, size_t n_values);
fmi2Status slave_set(struct instance *in, const char *method, char kind, const unsigned vr[],
                     size_t n, const void *value, size_t n_values);
fmi2Status slave_get_state(struct instance *in, fmi2FMUstate *state);
/* `refused`: the slave kept every value as it was (its outputs' cache too). */
fmi2Status slave_set_state(struct instance *in, fmi2FMUstate state, int *refused);
fmi2Status slave_free_state(fmi2FMUstate *state);
fmi2Status slave_state_bytes(struct instance *in, fmi2FMUstate state, char *bytes, size_t *size);
fmi2Status slave_state_from_bytes(struct instance *in, const char *bytes, size_t size,
                                  fmi2FMUstate *state);
/* Instantiate's shared part (calls.c): the instance, or NULL (freed, logged). */
struct instance *start_instance(struct instance *in, const char *name, const char *guid,
                                const char *location, const char *resources, int visible,
                                int logging_on, void *logger);
/* Every part of an instance released, the instance freed (calls.c). */
void free_instance(struct instance *in);
void report(struct instance *in, fmi2Status status, const char *category, const char *text);
void reportf(struct instance *in, fmi2Status status, const char *format, ...)
    __attribute__((format(printf, 3, 4)));

#endif
