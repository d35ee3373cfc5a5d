/* Import the slave's script module before pythonfmu does: pythonfmu 0.7.0 and
 * pythonfmu3 0.3.4 dereference NULL in their instance constructor when the
 * import fails (slavemodule.txt empty, missing or naming another module), which
 * kills the host.  The import runs in the process's Python (started or found
 * by python_runtime.c) with the resources folder first on sys.path, as
 * pythonfmu puts it; sys.path is left as it was, and the imported module stays
 * in sys.modules, where pythonfmu's own import finds it. */
#define _GNU_SOURCE
#include "fast_path.h"

#include <dlfcn.h>
#include <stdio.h>
#include <string.h>

/* No Python.h (see python_runtime.c): the few types and prototypes used here,
 * one ABI for CPython 3.10-3.13. */
typedef int PyGILState_STATE; /* an enum in Python.h */
#define PY_FILE_INPUT 257    /* PY_FILE_INPUT, the same in every CPython 3 */

#define IMPORT_FUNCTIONS(X)                                                              \
    X(PyGILState_STATE, PyGILState_Ensure, (void))                                       \
    X(void, PyGILState_Release, (PyGILState_STATE)) X(PyObject *, PyDict_New, (void))    \
    X(PyObject *, PyEval_GetBuiltins, (void))                                            \
    X(int, PyDict_SetItemString, (PyObject *, const char *, PyObject *))                 \
    X(PyObject *, PyDict_GetItemString, (PyObject *, const char *))                      \
    X(PyObject *, PyUnicode_DecodeFSDefault, (const char *))                             \
    X(PyObject *, PyUnicode_FromString, (const char *))                                  \
    X(PyObject *, PyRun_String, (const char *, int, PyObject *, PyObject *))             \
    X(const char *, PyUnicode_AsUTF8, (PyObject *)) X(void, Py_DecRef, (PyObject *))     \
    X(void, PyErr_Clear, (void))

static const char CHECK[] =
    "import sys, importlib\n"
    "sys.path.insert(0, resources)\n"
    "try:\n"
    "    importlib.import_module(module)\n"
    "    problem = ''\n"
    "except BaseException as error:\n"
    "    problem = f'{type(error).__name__}: {error}'\n"
    "finally:\n"
    "    del sys.path[sys.path.index(resources)]\n";

static int read_module_name(const char *resources, char *module, size_t length, char *error,
                            size_t size)
{
    char name[4200];
    snprintf(name, sizeof name, "%s/slavemodule.txt", resources);
    FILE *file = fopen(name, "r");
    int found = file && fgets(module, (int)length, file);
    if (file)
        fclose(file);
    if (found) /* else module holds nothing of the file's, not even a terminator */
        module[strcspn(module, "\r\n")] = '\0';
    if (!found || !*module) {
        snprintf(error, size, "cannot read the slave's module name from %s: the resources "
                              "folder is incomplete, rebuild the FMU", name);
        return -1;
    }
    return 0;
}

int slave_module_imports(const char *resources, char *error, size_t size)
{
    char module[256];
    if (read_module_name(resources, module, sizeof module, error, size))
        return -1;
#define DECLARE(result, name, parameters)                                                 \
    result(*p_##name) parameters = (result(*) parameters)dlsym(RTLD_DEFAULT, #name);
    IMPORT_FUNCTIONS(DECLARE)
#undef DECLARE
#define MISSING(result, name, parameters) !p_##name ||
    if (IMPORT_FUNCTIONS(MISSING) 0) {
        snprintf(error, size, "the process's Python lacks a function the loader needs");
        return -1;
    }
#undef MISSING
    PyGILState_STATE gil = p_PyGILState_Ensure();
    PyObject *globals = p_PyDict_New(), *path = p_PyUnicode_DecodeFSDefault(resources);
    PyObject *name = p_PyUnicode_FromString(module), *result = NULL;
    if (globals && path && name && !p_PyDict_SetItemString(globals, "resources", path) &&
        !p_PyDict_SetItemString(globals, "module", name) &&
        !p_PyDict_SetItemString(globals, "__builtins__", p_PyEval_GetBuiltins()))
        result = p_PyRun_String(CHECK, PY_FILE_INPUT, globals, globals);
    PyObject *problem = result && globals ? p_PyDict_GetItemString(globals, "problem") : NULL;
    const char *text = problem ? p_PyUnicode_AsUTF8(problem) : "the check itself failed";
    int failed = !text || *text;
    if (failed)
        snprintf(error, size, "the slave's module %s, named in %s/slavemodule.txt, does not "
                 "import from there (%s)", module, resources, text ? text : "unknown error");
    p_PyErr_Clear();
    PyObject *owned[] = {result, name, path, globals};
    for (size_t i = 0; i < sizeof owned / sizeof *owned; i++)
        if (owned[i])
            p_Py_DecRef(owned[i]);
    p_PyGILState_Release(gil);
    return failed ? -1 : 0;
}

/* Whether the slave has left initialization (its `_initialized`, which its FMU
 * state carries): 1, 0, or -1 when it cannot tell. */
int fast_initialized(struct instance *in)
{
#define FLAG_FUNCTIONS(X)                                                                 \
    X(PyGILState_STATE, PyGILState_Ensure, (void))                                       \
    X(void, PyGILState_Release, (PyGILState_STATE))                                      \
    X(PyObject *, PyObject_GetAttrString, (PyObject *, const char *))                    \
    X(int, PyObject_IsTrue, (PyObject *)) X(void, Py_DecRef, (PyObject *))               \
    X(void, PyErr_Clear, (void))
#define DECLARE(result, name, parameters)                                                 \
    result(*p_##name) parameters = (result(*) parameters)dlsym(RTLD_DEFAULT, #name);
    FLAG_FUNCTIONS(DECLARE)
#undef DECLARE
#define MISSING(result, name, parameters) !p_##name ||
    if (!in->fast || FLAG_FUNCTIONS(MISSING) 0)
        return -1;
#undef MISSING
    PyGILState_STATE gil = p_PyGILState_Ensure();
    PyObject *flag = p_PyObject_GetAttrString(in->fast->slave, "_initialized");
    int initialized = flag ? p_PyObject_IsTrue(flag) : -1;
    if (flag)
        p_Py_DecRef(flag);
    p_PyErr_Clear();
    p_PyGILState_Release(gil);
    return initialized;
}
