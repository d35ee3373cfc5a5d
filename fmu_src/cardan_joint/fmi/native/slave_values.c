/* The slave's values and FMU states through its Python methods, as pythonfmu
 * 0.7.0 and pythonfmu3 0.3.4 called them (get_<type>/set_<type> on lists: the
 * value references, and for a setter the values, flattened; FMU states are the
 * objects _get_fmu_state returns, one reference each, in bytes through
 * _fmu_state_to_bytes / _fmu_state_from_bytes), FMI 2.0 and 3.0 alike. */
#include "python_api.h"

#include <stdio.h>
#include <string.h>

static PyObject *references(const unsigned vr[], size_t n)
{
    PyObject *list = p_PyList_New((Py_ssize_t)n);
    for (size_t i = 0; list && i < n; i++)
        p_PyList_SetItem(list, (Py_ssize_t)i, p_PyLong_FromUnsignedLong(vr[i]));
    return list;
}

/* get_<type>(vrs): its list's items into value (kind 'd', 'i', 'b' or 's'), which
 * holds n_values: a list of another length is refused, never copied. */
fmi2Status slave_get(struct instance *in, const char *method, char kind, const unsigned vr[],
                     size_t n, void *value, size_t n_values)
{
    PyGILState_STATE gil = p_PyGILState_Ensure();
    PyObject *vrs = references(vr, n);
    PyObject *result = vrs ? p_PyObject_CallMethod(in->object, method, "(O)", vrs) : NULL;
    if (vrs)
        p_Py_DecRef(vrs);
    Py_ssize_t size = result ? p_PyList_Size(result) : (Py_ssize_t)n_values; /* -1: no list */
    fmi2Status status = slave_finish(in, result, method);
    if (size != (Py_ssize_t)n_values) {
        reportf(in, fmi2Fatal, "the slave's %s gave %zd values (-1: no list) for %zu values "
                "of %zu value references", method, size, n_values, n);
        p_Py_DecRef(result);
        result = NULL;
        status = fmi2Fatal;
    }
    for (size_t i = 0; result && i < n_values; i++) {
        PyObject *item = p_PyList_GetItem(result, (Py_ssize_t)i);
        if (kind == 'd')
            ((double *)value)[i] = p_PyFloat_AsDouble(item);
        else if (kind == 'i')
            ((int *)value)[i] = (int)p_PyLong_AsLong(item);
        else if (kind == 'b')
            ((int *)value)[i] = p_PyObject_IsTrue(item);
        else
            ((const char **)value)[i] = p_PyUnicode_AsUTF8(item);
    }
    p_PyErr_Clear();
    if (kind == 's' && result) {  /* the strings live until the next getString */
        if (in->strings)
            p_Py_DecRef(in->strings);
        in->strings = result;
    } else if (result) {
        p_Py_DecRef(result);
    }
    p_PyGILState_Release(gil);
    return status;
}

static PyObject *item(char kind, const void *value, size_t i)
{
    if (kind == 'd')
        return p_PyFloat_FromDouble(((const double *)value)[i]);
    if (kind == 'i')
        return p_PyLong_FromLong(((const int *)value)[i]);
    if (kind == 'b')
        return p_PyBool_FromLong(((const int *)value)[i]);
    const char *text = ((const char *const *)value)[i];
    return p_PyUnicode_FromString(text ? text : "");
}

/* Value i could not become a Python object: a string that is not UTF-8 (or no
 * memory).  Named, so that the host sees which value of the call was bad. */
static void refuse_value(struct instance *in, char kind, const unsigned vr[], size_t n,
                         const void *value, size_t i, size_t n_values)
{
    p_PyErr_Clear();
    char name[64] = "", bytes[3 * 8 + 4] = "";
    unsigned reference = vr[n == n_values ? i : 0];
    if (variable_name(in->resources, reference, name, sizeof name))
        snprintf(name, sizeof name, "no variable");
    if (kind != 's') {
        reportf(in, fmi2Error, "value %zu, for %s (value reference %u), could not be passed "
                "to the slave (out of memory); the call was ignored", i, name, reference);
        return;
    }
    const unsigned char *text = ((const unsigned char *const *)value)[i];
    for (size_t k = 0, used = 0; text[k] && k < 8; k++, used = strlen(bytes))
        snprintf(bytes + used, sizeof bytes - used, "%s%02x", k ? " " : "", text[k]);
    reportf(in, fmi2Error, "the String value %zu, for %s (value reference %u), is not UTF-8 "
            "text (it begins with the bytes %s%s); the call was ignored, nothing was set", i,
            name, reference, bytes, strlen((const char *)text) > 8 ? " ..." : "");
}

/* set_<type>(vrs, values) (kind as for slave_get); a value that cannot be made a
 * Python object is refused by name before the slave is called. */
fmi2Status slave_set(struct instance *in, const char *method, char kind, const unsigned vr[],
                     size_t n, const void *value, size_t n_values)
{
    PyGILState_STATE gil = p_PyGILState_Ensure();
    PyObject *vrs = references(vr, n), *values = p_PyList_New((Py_ssize_t)n_values);
    for (size_t i = 0; vrs && values && i < n_values; i++) {
        PyObject *one = item(kind, value, i);
        if (!one) { /* never a NULL item, nor a call with an exception set */
            refuse_value(in, kind, vr, n, value, i, n_values);
            p_Py_DecRef(vrs);
            p_Py_DecRef(values);
            p_PyGILState_Release(gil);
            return fmi2Error;
        }
        p_PyList_SetItem(values, (Py_ssize_t)i, one);
    }
    PyObject *result =
        vrs && values ? p_PyObject_CallMethod(in->object, method, "(OO)", vrs, values) : NULL;
    fmi2Status status = slave_finish(in, result, method);
    PyObject *owned[] = {result, vrs, values};
    for (size_t k = 0; k < 3; k++)
        if (owned[k])
            p_Py_DecRef(owned[k]);
    p_PyGILState_Release(gil);
    return status;
}

/* --- FMU states: the slave's own objects (_get_fmu_state), one reference each -- */

fmi2Status slave_get_state(struct instance *in, fmi2FMUstate *state)
{
    PyGILState_STATE gil = p_PyGILState_Ensure();
    PyObject *result = p_PyObject_CallMethod(in->object, "_get_fmu_state", NULL);
    fmi2Status status = slave_finish(in, result, "_get_fmu_state");
    *state = result;
    p_PyGILState_Release(gil);
    return status;
}

fmi2Status slave_set_state(struct instance *in, fmi2FMUstate state, int *refused)
{
    PyGILState_STATE gil = p_PyGILState_Ensure();
    PyObject *result = p_PyObject_CallMethod(in->object, "_set_fmu_state", "(O)", state);
    *refused = result && p_PyObject_IsTrue(result) == 1;
    fmi2Status status = slave_finish(in, result, "_set_fmu_state");
    if (result)
        p_Py_DecRef(result);
    p_PyGILState_Release(gil);
    return status;
}

fmi2Status slave_free_state(fmi2FMUstate *state)
{
    PyGILState_STATE gil = p_PyGILState_Ensure();
    p_Py_DecRef(*state);
    p_PyGILState_Release(gil);
    *state = NULL;
    return fmi2OK;
}

/* The state's bytes (_fmu_state_to_bytes): their size, and copied into bytes
 * when it is not NULL (at most `size`). */
fmi2Status slave_state_bytes(struct instance *in, fmi2FMUstate state, char *bytes, size_t *size)
{
    PyGILState_STATE gil = p_PyGILState_Ensure();
    PyObject *result = p_PyObject_CallMethod(in->object, "_fmu_state_to_bytes", "(O)", state);
    char *data = NULL;
    Py_ssize_t length = 0;
    if (result && p_PyBytes_AsStringAndSize(result, &data, &length)) {
        p_Py_DecRef(result);
        result = NULL;
    }
    fmi2Status status = slave_finish(in, result, "_fmu_state_to_bytes");
    if (result && bytes)
        memcpy(bytes, data, (size_t)length < *size ? (size_t)length : *size);
    if (result && !bytes)
        *size = (size_t)length;
    if (result)
        p_Py_DecRef(result);
    p_PyGILState_Release(gil);
    return status;
}

fmi2Status slave_state_from_bytes(struct instance *in, const char *bytes, size_t size,
                                  fmi2FMUstate *state)
{
    PyGILState_STATE gil = p_PyGILState_Ensure();
    PyObject *data = p_PyBytes_FromStringAndSize(bytes, (Py_ssize_t)size);
    PyObject *result =
        data ? p_PyObject_CallMethod(in->object, "_fmu_state_from_bytes", "(O)", data) : NULL;
    fmi2Status status = slave_finish(in, result, "_fmu_state_from_bytes");
    if (result == py_none) { /* refused: the slave has logged why, at Error */
        p_Py_DecRef(result);
        result = NULL;
        if (in->worst < fmi2Error)
            report(in, fmi2Error, NULL, "the slave refused the serialized FMU state");
        status = fmi2Error;
    }
    *state = result;
    if (data)
        p_Py_DecRef(data);
    p_PyGILState_Release(gil);
    return status;
}
