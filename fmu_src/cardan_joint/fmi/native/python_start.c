/* Starting CPython in a process that has none, isolated, with the home and
 * search path discovery found, UTF-8 mode on, no site import and no signal
 * handlers: through the API its minor has (config_layout.h, one entry per minor).
 *
 * Py_InitializeEx prints a fatal error and exits the process when the
 * standard library is broken (encodings unimportable); both configuration APIs
 * return that as a status, which becomes the instance's message instead.
 * No Python headers (see python_runtime.c): PyStatus and PyWideStringList have
 * one ABI in 3.10-3.13; PEP 741's functions take names and C strings.
 */
#define _GNU_SOURCE
#include "config_layout.h"
#include "loader.h"

#include <dlfcn.h>
#include <limits.h>
#include <stdalign.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
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

static const struct cpython_minor *minor_entry(int minor)
{
    for (size_t i = 0; i < N_CPYTHON_MINORS; i++)
        if (CPYTHON_MINORS[i].minor == minor)
            return &CPYTHON_MINORS[i];
    return NULL;
}

#define INIT_CONFIG_FUNCTIONS(X)                                                         \
    X(void *, PyInitConfig_Create, (void)) X(void, PyInitConfig_Free, (void *))          \
    X(int, PyInitConfig_GetError, (void *, const char **))                               \
    X(int, PyInitConfig_SetInt, (void *, const char *, int64_t))                         \
    X(int, PyInitConfig_SetStr, (void *, const char *, const char *))                    \
    X(int, PyInitConfig_SetStrList, (void *, const char *, size_t, char *const *))       \
    X(int, Py_InitializeFromInitConfig, (void *))

#define DECLARE(result, name, parameters)                                                \
    result(*name) parameters = (result(*) parameters)dlsym(library, #name);              \
    if (!name) {                                                                         \
        snprintf(error, size, "%s has no %s: not the CPython 3.%d it says it is",        \
                 python->library, #name, minor);                                         \
        return -1;                                                                       \
    }

/* PEP 741 (3.14 on): options by name, strings as UTF-8 (UTF-8 mode is on). */
static int start_by_names(void *library, int minor, const struct python_location *python,
                          char *error, size_t size)
{
    INIT_CONFIG_FUNCTIONS(DECLARE)
    void *config = PyInitConfig_Create(); /* the isolated configuration */
    if (!config) {
        snprintf(error, size, "Python %s: no memory for its configuration", python->library);
        return -1;
    }
    /* As many entries as the path holds: one more than its separators at most. */
    char entries[sizeof python->path];
    size_t n = 0, room = 1;
    snprintf(entries, sizeof entries, "%s", python->path);
    for (const char *c = entries; *c; c++)
        room += *c == ':';
    char **items = malloc(room * sizeof *items);
    if (!items) {
        snprintf(error, size, "Python %s: no memory for its %zu path entries", python->library,
                 room);
        PyInitConfig_Free(config);
        return -1;
    }
    for (char *save, *entry = strtok_r(entries, ":", &save); entry;
         entry = strtok_r(NULL, ":", &save))
        items[n++] = entry;
    const char *failed = PyInitConfig_SetInt(config, "utf8_mode", 1) ? "utf8_mode"
        : PyInitConfig_SetInt(config, "site_import", 0) ? "site_import"
        : PyInitConfig_SetInt(config, "install_signal_handlers", 0) ? "install_signal_handlers"
        : PyInitConfig_SetStr(config, "home", python->home) ? "home"
        : PyInitConfig_SetStrList(config, "module_search_paths", n, items)
            ? "module_search_paths"
        : PyInitConfig_SetInt(config, "module_search_paths_set", 1) ? "module_search_paths_set"
        : NULL;
    int started = failed ? -1 : Py_InitializeFromInitConfig(config);
    const char *message = NULL;
    if (failed || started < 0)
        PyInitConfig_GetError(config, &message);
    if (failed)
        snprintf(error, size, "Python %s refused the option %s: %s", python->library, failed,
                 message ? message : "no reason given");
    else if (started < 0)
        snprintf(error, size, "Python %s did not start with home '%s' and path '%s': %s; "
                 FIX_HINT, python->library, python->home, python->path,
                 message ? message : "exit requested");
    PyInitConfig_Free(config);
    free(items);
    return failed ? -1 : started < 0 ? -2 : 0;
}

/* Up to 3.13: a PyConfig struct, its fields at the table's offsets. */
static int start_by_offsets(void *library, int minor, const struct cpython_minor *layout,
                            const struct python_location *python, char *error, size_t size)
{
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

int start_interpreter(void *library, int minor, const struct python_location *python,
                      char *error, size_t size)
{
    const struct cpython_minor *entry = minor_entry(minor);
    if (!entry) {
        snprintf(error, size, "%s is CPython 3.%d; this FMU's runtime starts CPython 3.%d to "
                 "3.%d (a minor it does not know is not started: rebuild the FMU with a newer "
                 "release of the project)", python->library, minor, OLDEST_MINOR,
                 NEWEST_MINOR);
        return -1;
    }
    if (!has_standard_library(python->path)) {
        snprintf(error, size, "the search path '%s' for Python %s has no standard library "
                 "(encodings/__init__.py); " FIX_HINT, python->path, python->library);
        return -1;
    }
    if (entry->api == INIT_CONFIG)
        return start_by_names(library, minor, python, error, size);
    return start_by_offsets(library, minor, entry, python, error, size);
}
