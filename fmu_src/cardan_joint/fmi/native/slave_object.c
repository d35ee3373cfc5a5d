/* The slave's Python object, constructed and called by the runtime itself (no
 * pythonfmu binary), for FMI 2.0 and 3.0: what pythonfmu 0.7.0's and
 * pythonfmu3 0.3.4's export libraries did, one Python call per FMI call.  The
 * slave class is the one class of the script module (resources/slavemodule.txt,
 * imported by slave_module.c) that derives from the FMI version's slave base
 * (SLAVE_BASE); it gets the keyword arguments both libraries pass
 * (instance_name, resources, visible; the runtime logs for the slave, so it
 * passes no logger).  After every call the slave's log queue goes to report()
 * (slave_drain); a Python exception is Fatal with pythonfmu's message. */
#include "python_api.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* The slave class as pythonfmu finds it, constructed as pythonfmu does. */
static const char CONSTRUCT[] =
    "import sys\n"
    "with open(resources + '/slavemodule.txt') as file:\n"
    "    script = sys.modules[file.readline().strip()]\n"
    "classes = [value for value in vars(script).values() if isinstance(value, type)\n"
    "           and value.__module__ == script.__name__\n"
    "           and any(b.__name__ == base for b in value.__mro__[1:])]\n"
    "if len(classes) != 1:\n"
    "    raise TypeError(f'{script.__name__} defines {len(classes)} classes deriving from '\n"
    "                    f'{base}: it must define one')\n"
    "slave = classes[0](instance_name=name, resources=resources, visible=visible)\n";

/* The slave's log queue to the host, as pythonfmu forwards it after its calls. */
void slave_drain(struct instance *in, PyObject *slave)
{
    /* By name at every call: a str kept across calls would outlive an
     * interpreter the host finalizes and starts again. */
    PyObject *queue = p_PyObject_GetAttrString(slave, "log_queue");
    Py_ssize_t n = queue ? p_PyList_Size(queue) : -1;
    for (Py_ssize_t i = 0; i < n; i++) {
        PyObject *item = p_PyList_GetItem(queue, i);
        PyObject *status = p_PyObject_GetAttrString(item, "status");
        PyObject *category = p_PyObject_GetAttrString(item, "category");
        PyObject *message = p_PyObject_GetAttrString(item, "msg");
        const char *text = message ? p_PyUnicode_AsUTF8(message) : NULL;
        int named = category && category != py_none;
        const char *kind = named ? p_PyUnicode_AsUTF8(category) : NULL;
        long level = status ? p_PyLong_AsLong(status) : fmi2Error;
        report(in, level >= 0 && level <= fmi2Fatal ? (fmi2Status)level : fmi2Error, kind,
               text ? text : "");
        PyObject *owned[] = {status, category, message};
        for (size_t k = 0; k < 3; k++)
            if (owned[k])
                p_Py_DecRef(owned[k]);
    }
    if (n > 0)
        p_PyList_SetSlice(queue, 0, n, NULL);
    if (queue)
        p_Py_DecRef(queue);
    p_PyErr_Clear();
}

/* A host that runs Python's own signal handlers (its Python, FMPy's) takes
 * Ctrl-C as KeyboardInterrupt at the next bytecode its main thread runs: the
 * slave's, during a call.  The interrupt is the host's: it gets it back, raised
 * at its own Python's next check, which the caller sets after the call's last
 * message (slave_hand_back): a host whose logger is Python (FMPy's callbacks)
 * would otherwise take it inside the logger, where ctypes drops it.  The slave
 * stopped part way through the call, so its state is no longer known: the
 * instance can only be reset or freed. */
int slave_interrupted(struct instance *in, const char *what)
{
    if (!p_PyErr_Occurred() || !p_PyErr_ExceptionMatches(*py_keyboard_interrupt))
        return 0;
    p_PyErr_Clear();
    in->state = STATE_ERROR;
    reportf(in, fmi2Error, "the slave's %s was interrupted by a KeyboardInterrupt (Ctrl-C) "
            "of the host's Python, which gets it back; the slave stopped part way, so the "
            "instance can only be reset or freed now", what);
    return 1;
}

void slave_hand_back(int interrupted)
{
    if (interrupted)
        p_PyErr_SetInterrupt();
}

fmi2Status slave_finish(struct instance *in, PyObject *result, const char *what)
{
    fmi2Status status = fmi2OK;
    int interrupted = !result && slave_interrupted(in, what);
    if (interrupted)
        status = fmi2Error;
    if (in->object)
        slave_drain(in, in->object);
    slave_hand_back(interrupted);
    if (!result && status == fmi2OK) {
        PyObject *type = NULL, *value = NULL, *traceback = NULL;
        p_PyErr_Fetch(&type, &value, &traceback);
        PyObject *repr = value ? p_PyObject_Repr(value) : NULL;
        const char *text = repr ? p_PyUnicode_AsUTF8(repr) : NULL;
        reportf(in, fmi2Fatal, "Fatal py exception encountered: [%s]\n%s", what,
                text ? text : "unknown error");
        PyObject *owned[] = {repr, type, value, traceback};
        for (size_t k = 0; k < 4; k++)
            if (owned[k])
                p_Py_DecRef(owned[k]);
        p_PyErr_Clear();
        status = fmi2Fatal;
    }
    return status;
}

/* A new slave object for the instance (at instantiate and reset): 0, else -1
 * and the slave's old object kept. */
int slave_construct(struct instance *in, const char *resources)
{
    if (!python_api()) {
        reportf(in, fmi2Fatal, "the process's Python lacks a function the runtime needs");
        return -1;
    }
    PyGILState_STATE gil = p_PyGILState_Ensure();
    PyObject *globals = p_PyDict_New(), *result = NULL;
    if (globals && set_global(globals, "resources", p_PyUnicode_DecodeFSDefault(resources)) &&
        set_global(globals, "name", p_PyUnicode_FromString(in->name)) &&
        set_global(globals, "visible", p_PyLong_FromLong(in->visible)) &&
        set_global(globals, "base", p_PyUnicode_FromString(SLAVE_BASE)))
        result = run_with(CONSTRUCT, globals);
    PyObject *slave = result ? p_PyDict_GetItemString(globals, "slave") : NULL;
    int failed = slave_finish(in, result, "instantiate") != fmi2OK || !slave;
    if (!failed) {
        p_Py_IncRef(slave);
        if (in->object)
            p_Py_DecRef(in->object);
        in->object = slave;
        slave_drain(in, slave);
    }
    if (result)
        p_Py_DecRef(result);
    if (globals)
        p_Py_DecRef(globals);
    p_PyGILState_Release(gil);
    return failed ? -1 : 0;
}

void slave_release(struct instance *in)
{
    if (!in->object && !in->strings)
        return;
    PyGILState_STATE gil = p_PyGILState_Ensure();
    if (in->object)
        p_Py_DecRef(in->object);
    if (in->strings)
        p_Py_DecRef(in->strings);
    in->object = in->strings = NULL;
    p_PyGILState_Release(gil);
}

/* With the GIL: a method call's result handed to slave_finish and released. */
static fmi2Status finished(struct instance *in, PyObject *result, const char *method)
{
    fmi2Status status = slave_finish(in, result, method);
    if (result)
        p_Py_DecRef(result);
    return status;
}

/* A method without arguments (enter/exit initialization, terminate). */
fmi2Status slave_call(struct instance *in, const char *method)
{
    PyGILState_STATE gil = p_PyGILState_Ensure();
    fmi2Status status = finished(in, p_PyObject_CallMethod(in->object, method, NULL), method);
    p_PyGILState_Release(gil);
    return status;
}

/* FMI 2.0: setup_experiment with the stored experiment, which pythonfmu 0.7.0
 * calls right before enter_initialization_mode. */
fmi2Status slave_setup_experiment(struct instance *in)
{
    PyGILState_STATE gil = p_PyGILState_Ensure();
    PyObject *stop = in->stop_defined ? p_PyFloat_FromDouble(in->stop) : py_none;
    PyObject *tolerance = in->tolerance_defined ? p_PyFloat_FromDouble(in->tolerance) : py_none;
    PyObject *result = p_PyObject_CallMethod(in->object, "setup_experiment", "(dOO)", in->start,
                                             stop, tolerance);
    if (stop != py_none)
        p_Py_DecRef(stop);
    if (tolerance != py_none)
        p_Py_DecRef(tolerance);
    fmi2Status status = finished(in, result, "setup_experiment");
    p_PyGILState_Release(gil);
    return status;
}

/* With the GIL: do_step's answer as pythonfmu3 reads it (a result with a
 * status and terminateSimulation) or pythonfmu (true: OK, else Discard). */
fmi2Status step_answer(PyObject *result, int *terminate)
{
    PyObject *status = p_PyObject_GetAttrString(result, "status");
    long value = status ? p_PyLong_AsLong(status) : (p_PyObject_IsTrue(result) == 1 ? 0 : 2);
    PyObject *ends = status ? p_PyObject_GetAttrString(result, "terminateSimulation") : NULL;
    if (terminate)
        *terminate = ends && p_PyObject_IsTrue(ends) == 1;
    if (status)
        p_Py_DecRef(status);
    if (ends)
        p_Py_DecRef(ends);
    p_PyErr_Clear();
    return value >= 0 && value <= fmi2Fatal ? (fmi2Status)value : fmi2Error;
}

/* doStep through the slave's do_step; `terminate` (may be NULL) as the slave says. */
fmi2Status slave_do_step(struct instance *in, double time, double step, int *terminate)
{
    PyGILState_STATE gil = p_PyGILState_Ensure();
    PyObject *result = p_PyObject_CallMethod(in->object, "do_step", "(dd)", time, step);
    fmi2Status answer = result ? step_answer(result, terminate) : fmi2OK;
    fmi2Status status = finished(in, result, "do_step");
    p_PyGILState_Release(gil);
    if (status == fmi2OK)
        status = answer;
    in->last_successful_time = status == fmi2OK ? time + step : time;
    return status;
}

/* Whether the slave has left initialization (its `_initialized`, which its FMU
 * state carries): 1, 0, or -1 when it cannot tell. */
int slave_initialized(struct instance *in)
{
    if (!in->object)
        return -1;
    PyGILState_STATE gil = p_PyGILState_Ensure();
    PyObject *flag = p_PyObject_GetAttrString(in->object, "_initialized");
    int initialized = flag ? p_PyObject_IsTrue(flag) : -1;
    if (flag)
        p_Py_DecRef(flag);
    p_PyErr_Clear();
    p_PyGILState_Release(gil);
    return initialized;
}
