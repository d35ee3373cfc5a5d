/* The Python C API as the runtime calls it once Python runs in the process:
 * one table, resolved once (python_api.c) in the process's global scope, with
 * no Python headers: one ABI for CPython 3.10-3.13.  (Starting Python, before
 * it is in the global scope, resolves its own few functions from the library:
 * python_runtime.c, python_start.c.) */
#ifndef CARDAN_JOINT_PYTHON_API_H
#define CARDAN_JOINT_PYTHON_API_H

#include "instance.h"

#include <sys/types.h>

typedef ssize_t Py_ssize_t;
typedef int PyGILState_STATE; /* an enum in Python.h */
#define PY_FILE_INPUT 257     /* the same in every CPython 3 */

#define PYTHON_FUNCTIONS(X)                                                                \
    X(PyGILState_STATE, PyGILState_Ensure, (void))                                        \
    X(void, PyGILState_Release, (PyGILState_STATE))                                       \
    X(PyObject *, PyObject_CallMethod, (PyObject *, const char *, const char *, ...))     \
    X(PyObject *, PyObject_CallFunctionObjArgs, (PyObject *, ...))                        \
    X(PyObject *, PyTuple_New, (Py_ssize_t))                                              \
    X(int, PyTuple_SetItem, (PyObject *, Py_ssize_t, PyObject *))                         \
    X(Py_ssize_t, PyTuple_Size, (PyObject *))                                             \
    X(PyObject *, PyTuple_GetItem, (PyObject *, Py_ssize_t))                              \
    X(PyObject *, PyObject_GetAttrString, (PyObject *, const char *))                     \
    X(PyObject *, PyList_New, (Py_ssize_t))                                               \
    X(int, PyList_SetItem, (PyObject *, Py_ssize_t, PyObject *))                          \
    X(PyObject *, PyList_GetItem, (PyObject *, Py_ssize_t))                               \
    X(Py_ssize_t, PyList_Size, (PyObject *))                                              \
    X(int, PyList_SetSlice, (PyObject *, Py_ssize_t, Py_ssize_t, PyObject *))             \
    X(PyObject *, PyLong_FromUnsignedLong, (unsigned long))                               \
    X(PyObject *, PyLong_FromLong, (long)) X(long, PyLong_AsLong, (PyObject *))           \
    X(PyObject *, PyFloat_FromDouble, (double)) X(double, PyFloat_AsDouble, (PyObject *)) \
    X(PyObject *, PyBool_FromLong, (long)) X(int, PyObject_IsTrue, (PyObject *))          \
    X(PyObject *, PyUnicode_FromString, (const char *))                                   \
    X(const char *, PyUnicode_AsUTF8, (PyObject *))                                       \
    X(PyObject *, PyUnicode_DecodeFSDefault, (const char *))                              \
    X(PyObject *, PyBytes_FromStringAndSize, (const char *, Py_ssize_t))                  \
    X(int, PyBytes_AsStringAndSize, (PyObject *, char **, Py_ssize_t *))                  \
    X(PyObject *, PyErr_Occurred, (void)) X(void, PyErr_Clear, (void))                    \
    X(int, PyErr_ExceptionMatches, (PyObject *)) X(void, PyErr_SetInterrupt, (void))      \
    X(void, PyErr_Fetch, (PyObject **, PyObject **, PyObject **))                         \
    X(PyObject *, PyObject_Repr, (PyObject *))                                            \
    X(void, Py_IncRef, (PyObject *)) X(void, Py_DecRef, (PyObject *))                     \
    X(PyObject *, PyDict_New, (void)) X(PyObject *, PyEval_GetBuiltins, (void))           \
    X(int, PyDict_SetItemString, (PyObject *, const char *, PyObject *))                  \
    X(PyObject *, PyDict_GetItemString, (PyObject *, const char *))                       \
    X(PyObject *, PyRun_String, (const char *, int, PyObject *, PyObject *))

#define DECLARE(result, name, parameters) extern result(*p_##name) parameters;
PYTHON_FUNCTIONS(DECLARE)
#undef DECLARE
extern PyObject *py_none;
/* The KeyboardInterrupt class (the address of PyExc_KeyboardInterrupt). */
extern PyObject *const *py_keyboard_interrupt;

/* 1 once every function above (and None) is found, else 0: call it before any. */
int python_api(void);

/* With the GIL: run `code` with `globals` (a new dict holding __builtins__ and
 * the caller's names); the result of PyRun_String (NULL: it raised). */
PyObject *run_with(const char *code, PyObject *globals);
/* With the GIL: globals[name] = value, the caller's reference to value taken
 * over; 0 when either is missing or the dict refused it. */
int set_global(PyObject *globals, const char *name, PyObject *value);

/* With the GIL, after a call into the slave that returned `result` (NULL: it
 * raised): the slave's log to the host, then the exception as pythonfmu
 * reports it (Fatal), or a KeyboardInterrupt handed back (Error,
 * slave_interrupted). */
fmi2Status slave_finish(struct instance *in, PyObject *result, const char *what);
/* With the GIL, after a call into the slave that raised: 1 when it raised
 * KeyboardInterrupt (said, cleared, the instance in STATE_ERROR), 0 otherwise
 * (the exception still set). */
int slave_interrupted(struct instance *in, const char *what);
/* With the GIL, after the call's last message: the KeyboardInterrupt handed
 * back to the host's Python if the slave took it (`interrupted`). */
void slave_hand_back(int interrupted);
/* With the GIL: do_step's result as an FMI status (pythonfmu3: its status and
 * terminateSimulation, into `terminate` if not NULL; pythonfmu: true is OK). */
fmi2Status step_answer(PyObject *result, int *terminate);

#endif
