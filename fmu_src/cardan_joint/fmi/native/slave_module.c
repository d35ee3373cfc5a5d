/* Import the slave's script module (resources/slavemodule.txt), whose class
 * slave_object.c constructs: a module that does not import (the file empty,
 * missing or naming another module) is a NULL instance and a message naming
 * the file, never a crash.  The import runs in the process's Python (started
 * or found by python_runtime.c) with the resources folder first on sys.path,
 * as pythonfmu puts it; sys.path is left as it was, and the imported module
 * stays in sys.modules, where slave_object.c finds it. */
#include "python_api.h"

#include <stdio.h>
#include <string.h>

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
    if (!python_api()) {
        snprintf(error, size, "the process's Python lacks a function the runtime needs");
        return -1;
    }
    PyGILState_STATE gil = p_PyGILState_Ensure();
    PyObject *globals = p_PyDict_New(), *result = NULL;
    if (globals && set_global(globals, "resources", p_PyUnicode_DecodeFSDefault(resources)) &&
        set_global(globals, "module", p_PyUnicode_FromString(module)))
        result = run_with(CHECK, globals);
    PyObject *problem = result && globals ? p_PyDict_GetItemString(globals, "problem") : NULL;
    const char *text = problem ? p_PyUnicode_AsUTF8(problem) : "the check itself failed";
    int failed = !text || *text;
    if (failed)
        snprintf(error, size, "the slave's module %s, named in %s/slavemodule.txt, does not "
                 "import from there (%s)", module, resources, text ? text : "unknown error");
    p_PyErr_Clear();
    PyObject *owned[] = {result, globals};
    for (size_t i = 0; i < sizeof owned / sizeof *owned; i++)
        if (owned[i])
            p_Py_DecRef(owned[i]);
    p_PyGILState_Release(gil);
    return failed ? -1 : 0;
}
