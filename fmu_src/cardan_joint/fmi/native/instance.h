/* One FMU instance as the loader sees it, and pythonfmu's fmi2 entry points. */
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

struct instance {
    unsigned magic;
    void *slave;
    const char *model;
    char *name, *guid, *resources_uri;
    fmi2Boolean visible;
    fmi2CallbackFunctions host;      /* the host's callbacks, as given */
    fmi2CallbackFunctions to_slave;  /* the same with this file's logger */
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

#define SLAVE_FUNCTIONS(X)                                                            \
    X(instantiate, fmi2Instantiate, fmi2Component, (fmi2String, fmi2Type, fmi2String,   \
      fmi2String, const fmi2CallbackFunctions *, fmi2Boolean, fmi2Boolean))            \
    X(free_instance, fmi2FreeInstance, void, (fmi2Component))                           \
    X(setup_experiment, fmi2SetupExperiment, fmi2Status, (fmi2Component, fmi2Boolean,   \
      fmi2Real, fmi2Real, fmi2Boolean, fmi2Real))                                       \
    X(enter_initialization, fmi2EnterInitializationMode, fmi2Status, (fmi2Component))   \
    X(exit_initialization, fmi2ExitInitializationMode, fmi2Status, (fmi2Component))     \
    X(terminate, fmi2Terminate, fmi2Status, (fmi2Component))                            \
    X(reset, fmi2Reset, fmi2Status, (fmi2Component))                                    \
    X(get_real, fmi2GetReal, fmi2Status, (fmi2Component, const fmi2ValueReference *,    \
      size_t, fmi2Real *))                                                              \
    X(get_integer, fmi2GetInteger, fmi2Status, (fmi2Component,                          \
      const fmi2ValueReference *, size_t, fmi2Integer *))                               \
    X(get_boolean, fmi2GetBoolean, fmi2Status, (fmi2Component,                          \
      const fmi2ValueReference *, size_t, fmi2Boolean *))                               \
    X(get_string, fmi2GetString, fmi2Status, (fmi2Component,                            \
      const fmi2ValueReference *, size_t, fmi2String *))                                \
    X(set_real, fmi2SetReal, fmi2Status, (fmi2Component, const fmi2ValueReference *,    \
      size_t, const fmi2Real *))                                                        \
    X(set_integer, fmi2SetInteger, fmi2Status, (fmi2Component,                          \
      const fmi2ValueReference *, size_t, const fmi2Integer *))                         \
    X(set_boolean, fmi2SetBoolean, fmi2Status, (fmi2Component,                          \
      const fmi2ValueReference *, size_t, const fmi2Boolean *))                         \
    X(set_string, fmi2SetString, fmi2Status, (fmi2Component,                            \
      const fmi2ValueReference *, size_t, const fmi2String *))                          \
    X(get_fmu_state, fmi2GetFMUstate, fmi2Status, (fmi2Component, fmi2FMUstate *))      \
    X(set_fmu_state, fmi2SetFMUstate, fmi2Status, (fmi2Component, fmi2FMUstate))        \
    X(free_fmu_state, fmi2FreeFMUstate, fmi2Status, (fmi2Component, fmi2FMUstate *))    \
    X(serialized_size, fmi2SerializedFMUstateSize, fmi2Status, (fmi2Component,          \
      fmi2FMUstate, size_t *))                                                          \
    X(serialize, fmi2SerializeFMUstate, fmi2Status, (fmi2Component, fmi2FMUstate,       \
      fmi2Byte *, size_t))                                                              \
    X(deserialize, fmi2DeSerializeFMUstate, fmi2Status, (fmi2Component,                 \
      const fmi2Byte *, size_t, fmi2FMUstate *))                                        \
    X(do_step, fmi2DoStep, fmi2Status, (fmi2Component, fmi2Real, fmi2Real, fmi2Boolean)) \
    X(get_real_status, fmi2GetRealStatus, fmi2Status, (fmi2Component, fmi2StatusKind,   \
      fmi2Real *))                                                                      \
    X(get_boolean_status, fmi2GetBooleanStatus, fmi2Status, (fmi2Component,             \
      fmi2StatusKind, fmi2Boolean *))

struct slave_api {
#define MEMBER(member, symbol, result, parameters) result(*member) parameters;
    SLAVE_FUNCTIONS(MEMBER)
#undef MEMBER
};
extern struct slave_api slave;

int resolve_slave_api(void *handle, char *error, size_t size);
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
int fast_last_successful_time(const struct instance *in, double *value);
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
void free_instance(struct instance *in);
void release_instance(struct instance *in, void (*free_slave)(void *));
void report(struct instance *in, fmi2Status status, const char *category, const char *text);
void reportf(struct instance *in, fmi2Status status, const char *format, ...)
    __attribute__((format(printf, 3, 4)));

#endif
