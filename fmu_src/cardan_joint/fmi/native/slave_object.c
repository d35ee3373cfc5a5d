/* The FMI 2.0 slave's Python object, constructed and called by the runtime
 * itself (no pythonfmu binary): what pythonfmu 0.7.0's export library did, one
 * Python call per fmi2 call.  The slave class is the one class of the script
 * module (resources/slavemodule.txt, imported by slave_module.c) that derives
 * from pythonfmu's Fmi2Slave; it gets pythonfmu's keyword arguments
 * (instance_name, resources, visible).  After every call the slave's log queue
 * goes to report() (slave_drain); a Python exception is fmi2Fatal with
 * pythonfmu's message.  Python is reached as in fast_path.c: no headers,
 * functions looked up in the process's global scope, one ABI for 3.10-3.13. */
#define _GNU_SOURCE
#include "slave_python.h"

#include <dlfcn.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define PY_FILE_INPUT 257

#define DECLARE(result, name, parameters) result(*p_##name) parameters;
OBJECT_FUNCTIONS(DECLARE)
#undef DECLARE
PyObject *py_none;

/* The slave class as pythonfmu finds it, constructed as pythonfmu does. */
static const char CONSTRUCT[] =
    "import sys\n"
    "with open(resources + '/slavemodule.txt') as file:\n"
    "    script = sys.modules[file.readline().strip()]\n"
    "classes = [value for value in vars(script).values() if isinstance(value, type)\n"
    "           and value.__module__ == script.__name__\n"
    "           and any(base.__name__ == 'Fmi2Slave' for base in value.__mro__[1:])]\n"
    "if len(classes) != 1:\n"
    "    raise TypeError(f'{script.__name__} defines {len(classes)} classes deriving from '\n"
    "                    'Fmi2Slave: it must define one')\n"
    "slave = classes[0](instance_name=name, resources=resources, visible=visible)\n";

static int resolve(void)
{
    static int resolved = -1;
    if (resolved >= 0)
        return resolved;
#define RESOLVE(result, name, parameters)                                                 \
    if (!(*(void **)&p_##name = dlsym(RTLD_DEFAULT, #name)))                              \
        return resolved = 0;
    OBJECT_FUNCTIONS(RESOLVE)
#undef RESOLVE
    py_none = dlsym(RTLD_DEFAULT, "_Py_NoneStruct");
    return resolved = py_none != NULL;
}

/* The slave's log queue to the host, as pythonfmu forwards it after its calls. */
void slave_drain(struct instance *in, PyObject *slave)
{
    if (!resolve())
        return;
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

/* With the GIL, after a call whose result is `result` (NULL: it raised): the
 * slave's log, then the exception as pythonfmu reports it. */
fmi2Status slave_finish(struct instance *in, PyObject *result, const char *what)
{
    fmi2Status status = fmi2OK;
    if (in->object)
        slave_drain(in, in->object);
    if (!result) {
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

static PyObject *global(PyObject *globals, const char *name, PyObject *value)
{
    if (value && p_PyDict_SetItemString(globals, name, value))
        return NULL;
    if (value)
        p_Py_DecRef(value);
    return value;
}

/* A new slave object for the instance (at instantiate and reset): 0, else -1
 * and the slave's old object kept. */
int slave_construct(struct instance *in, const char *resources)
{
    if (!resolve()) {
        reportf(in, fmi2Fatal, "the process's Python lacks a function the runtime needs");
        return -1;
    }
    PyGILState_STATE gil = p_PyGILState_Ensure();
    PyObject *globals = p_PyDict_New(), *result = NULL;
    if (globals && global(globals, "resources", p_PyUnicode_DecodeFSDefault(resources)) &&
        global(globals, "name", p_PyUnicode_FromString(in->name)) &&
        global(globals, "visible", p_PyLong_FromLong(in->visible)) &&
        !p_PyDict_SetItemString(globals, "__builtins__", p_PyEval_GetBuiltins()))
        result = p_PyRun_String(CONSTRUCT, PY_FILE_INPUT, globals, globals);
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

/* A method without arguments (enter/exit initialization, terminate); setup is
 * setup_experiment with the stored experiment, then enter_initialization_mode,
 * as pythonfmu 0.7.0 calls them. */
fmi2Status slave_call(struct instance *in, const char *method)
{
    PyGILState_STATE gil = p_PyGILState_Ensure();
    fmi2Status status = fmi2OK;
    if (strcmp(method, "enter_initialization_mode") == 0) {
        PyObject *stop = in->stop_defined ? p_PyFloat_FromDouble(in->stop) : py_none;
        PyObject *tolerance =
            in->tolerance_defined ? p_PyFloat_FromDouble(in->tolerance) : py_none;
        PyObject *result = p_PyObject_CallMethod(in->object, "setup_experiment", "(dOO)",
                                                 in->start, stop, tolerance);
        if (stop != py_none)
            p_Py_DecRef(stop);
        if (tolerance != py_none)
            p_Py_DecRef(tolerance);
        status = slave_finish(in, result, "setup_experiment");
        if (result)
            p_Py_DecRef(result);
    }
    if (status == fmi2OK) {
        PyObject *result = p_PyObject_CallMethod(in->object, method, NULL);
        status = slave_finish(in, result, method);
        if (result)
            p_Py_DecRef(result);
    }
    p_PyGILState_Release(gil);
    return status;
}

/* doStep through the slave's do_step: OK, or Discard when it returns false. */
fmi2Status slave_do_step(struct instance *in, double time, double step)
{
    PyGILState_STATE gil = p_PyGILState_Ensure();
    PyObject *result = p_PyObject_CallMethod(in->object, "do_step", "(dd)", time, step);
    int taken = result ? p_PyObject_IsTrue(result) : 0;
    fmi2Status status = slave_finish(in, result, "do_step");
    if (result)
        p_Py_DecRef(result);
    p_PyGILState_Release(gil);
    if (status == fmi2OK && taken != 1)
        status = fmi2Discard;
    in->last_successful_time = status == fmi2OK ? time + step : time;
    return status;
}
