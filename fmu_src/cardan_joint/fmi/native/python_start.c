/* Starting CPython in a process that has none, through the config API.
 *
 * Py_InitializeEx prints a fatal error and exits the process when the
 * standard library is broken (encodings unimportable); Py_InitializeFromConfig
 * returns that as a PyStatus, which becomes the instance's message instead.
 * No Python headers (see python_runtime.c): PyStatus and PyWideStringList have
 * one ABI in 3.10-3.13, PyConfig's fields are found through config_layout.h.
 */
#define _GNU_SOURCE
#include "config_layout.h"
#include "loader.h"

#include <dlfcn.h>
#include <limits.h>
#include <stdalign.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>
#include <wchar.h>

typedef struct {
    int type; /* 0 ok, 1 error, 2 exit */
    const char *func;
    const char *err_msg;
    int exitcode;
} PyStatus;
typedef struct {
    ptrdiff_t length;
    wchar_t **items;
} PyWideStringList;

#define CONFIG_FUNCTIONS(X)                                                              \
    X(void, PyPreConfig_InitIsolatedConfig, (void *))                                    \
    X(PyStatus, Py_PreInitialize, (const void *))                                        \
    X(void, PyConfig_InitIsolatedConfig, (void *)) X(void, PyConfig_Clear, (void *))     \
    X(PyStatus, PyConfig_SetBytesString, (void *, wchar_t **, const char *))             \
    X(PyStatus, PyWideStringList_Append, (PyWideStringList *, const wchar_t *))          \
    X(PyStatus, Py_InitializeFromConfig, (const void *))                                 \
    X(wchar_t *, Py_DecodeLocale, (const char *, size_t *)) X(void, PyMem_RawFree, (void *))

/* Py_InitializeEx aborts the process when it cannot import encodings, and the
 * config API's own message for it is terse: refuse a search path without it. */
static int has_standard_library(const char *path)
{
    char entries[sizeof ((struct python_location *)0)->path], probe[PATH_MAX];
    snprintf(entries, sizeof entries, "%s", path);
    for (char *save, *entry = strtok_r(entries, ":", &save); entry;
         entry = strtok_r(NULL, ":", &save)) {
        snprintf(probe, sizeof probe, "%s/encodings/__init__.py", entry);
        size_t n = strlen(entry);
        if (access(probe, R_OK) == 0 || (n > 4 && strcmp(entry + n - 4, ".zip") == 0 &&
                                         access(entry, R_OK) == 0))
            return 1;
    }
    return 0;
}

static const struct config_layout *layout_of(int minor)
{
    for (size_t i = 0; i < N_CONFIG_LAYOUTS; i++)
        if (CONFIG_LAYOUTS[i].minor == minor)
            return &CONFIG_LAYOUTS[i];
    return NULL;
}

int start_interpreter(void *library, int minor, const struct python_location *python,
                      char *error, size_t size)
{
    const struct config_layout *layout = layout_of(minor);
    if (!layout) {
        snprintf(error, size, "%s is CPython 3.%d; this FMU starts CPython 3.10 to 3.%d",
                 python->library, minor, NEWEST_MINOR);
        return -1;
    }
    if (!has_standard_library(python->path)) {
        snprintf(error, size, "the search path '%s' for Python %s has no standard library "
                 "(encodings/__init__.py); " FIX_HINT, python->path, python->library);
        return -1;
    }
#define DECLARE(result, name, parameters)                                                \
    result(*name) parameters = (result(*) parameters)dlsym(library, #name);              \
    if (!name) {                                                                         \
        snprintf(error, size, "%s has no %s: not a CPython 3.10 to 3.13", python->library, \
                 #name);                                                                 \
        return -1;                                                                       \
    }
    CONFIG_FUNCTIONS(DECLARE)
#undef DECLARE
    /* UTF-8 mode: a C-locale host (no LANG) would otherwise give Python ASCII file
     * names, and a resources path such as /opt/fmus/résumé could not be used. */
    alignas(8) char preconfig[PRECONFIG_SIZE];
    PyPreConfig_InitIsolatedConfig(preconfig);
    *(int *)(preconfig + PRECONFIG_UTF8_MODE) = 1;
    PyStatus status = Py_PreInitialize(preconfig);
    if (status.type != 0) {
        snprintf(error, size, "Python %s did not pre-initialize: %s", python->library,
                 status.err_msg ? status.err_msg : "exit requested");
        return -2;
    }
    static alignas(64) char config[CONFIG_ROOM];  /* used once per process, under its lock */
    PyConfig_InitIsolatedConfig(config);
    *(int *)(config + layout->site_import) = 0;             /* the path is all */
    *(int *)(config + layout->install_signal_handlers) = 0; /* the host owns its signals */
    status = PyConfig_SetBytesString(
        config, (wchar_t **)(config + layout->home), python->home);
    char entries[sizeof python->path];
    snprintf(entries, sizeof entries, "%s", python->path);
    for (char *save, *entry = strtok_r(entries, ":", &save); entry && status.type == 0;
         entry = strtok_r(NULL, ":", &save)) {
        wchar_t *wide = Py_DecodeLocale(entry, NULL);
        if (!wide) {
            snprintf(error, size, "cannot decode the Python path entry '%s'", entry);
            PyConfig_Clear(config);
            return -1;
        }
        status = PyWideStringList_Append(
            (PyWideStringList *)(config + layout->module_search_paths), wide);
        PyMem_RawFree(wide);
    }
    *(int *)(config + layout->module_search_paths_set) = 1;
    if (status.type == 0)
        status = Py_InitializeFromConfig(config);
    PyConfig_Clear(config);
    if (status.type != 0) {
        snprintf(error, size, "Python %s did not start with home '%s' and path '%s': %s%s%s; "
                 FIX_HINT, python->library, python->home, python->path,
                 status.func ? status.func : "", status.func ? ": " : "",
                 status.err_msg ? status.err_msg : "exit requested");
        return -2;
    }
    return 0;
}
