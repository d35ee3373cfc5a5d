/* The Python C API functions the FMI 2.0 slave's calls use (slave_object.c
 * resolves them, slave_values.c shares them): no Python headers, looked up in
 * the process's global scope, one ABI for CPython 3.10-3.13. */
#ifndef CARDAN_JOINT_SLAVE_PYTHON_H
#define CARDAN_JOINT_SLAVE_PYTHON_H

#include "instance.h"

#include <sys/types.h>

typedef ssize_t Py_ssize_t;
typedef int PyGILState_STATE; /* an enum in Python.h */

#define OBJECT_FUNCTIONS(X)                                                                \
    X(PyGILState_STATE, PyGILState_Ensure, (void))                                        \
    X(void, PyGILState_Release, (PyGILState_STATE))                                       \
    X(PyObject *, PyObject_CallMethod, (PyObject *, const char *, const char *, ...))     \
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
    X(void, PyErr_Fetch, (PyObject **, PyObject **, PyObject **))                         \
    X(PyObject *, PyObject_Repr, (PyObject *))                                            \
    X(void, Py_IncRef, (PyObject *)) X(void, Py_DecRef, (PyObject *))                     \
    X(PyObject *, PyDict_New, (void)) X(PyObject *, PyEval_GetBuiltins, (void))           \
    X(int, PyDict_SetItemString, (PyObject *, const char *, PyObject *))                  \
    X(PyObject *, PyDict_GetItemString, (PyObject *, const char *))                       \
    X(PyObject *, PyRun_String, (const char *, int, PyObject *, PyObject *))

#define DECLARE(result, name, parameters) extern result(*p_##name) parameters;
OBJECT_FUNCTIONS(DECLARE)
#undef DECLARE
extern PyObject *py_none;

/* With the GIL, after a call into the slave that returned `result` (NULL: it
 * raised): the slave's log to the host, then the exception as pythonfmu
 * reported it (fmi2Fatal). */
fmi2Status slave_finish(struct instance *in, PyObject *result, const char *what);

#endif
