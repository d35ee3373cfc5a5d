/* Which Python to start in a host process that has none.
 *
 * The user's ($CARDAN_JOINT_FMU_PYTHON_*), else the build's if it is still
 * there, else the machine's own CPython, found from files as its dynamic
 * linker and its distribution lay it out: libpython3.X.so.1.0 in a default
 * library directory or in /etc/ld.so.cache, its standard library at
 * <prefix>/lib/python3.X beside it (or one level up, from a multiarch
 * directory).  The build's minor first, then the newest.  Nothing is run: a
 * host's dlopen or fmi2Instantiate must not spawn processes (no ldconfig -p).
 */
#define _GNU_SOURCE
#include "config_layout.h"
#include "loader.h"

#include <dlfcn.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#if defined(__x86_64__)
#define MULTIARCH "x86_64-linux-gnu"
#elif defined(__aarch64__)
#define MULTIARCH "aarch64-linux-gnu"
#else
#define MULTIARCH "."
#endif

static const char *const LIBRARY_DIRECTORIES[] = {
    "/usr/lib/" MULTIARCH, "/lib/" MULTIARCH, "/usr/lib64", "/lib64",
    "/usr/lib", "/lib", "/usr/local/lib", "/usr/local/lib64",
};
#define N_DIRECTORIES (sizeof LIBRARY_DIRECTORIES / sizeof *LIBRARY_DIRECTORIES)
#define LINKER_CACHE "/etc/ld.so.cache"

static int exists(const char *directory, const char *name)
{
    char path[PATH_MAX + 64];
    snprintf(path, sizeof path, "%s/%s", directory, name);
    return access(path, R_OK) == 0;
}

/* 12 for ".../libpython3.12.so.1.0", -1 if the name says no minor. */
static int minor_of_library(const char *library)
{
    const char *name = strrchr(library, '/');
    int minor;
    return sscanf(name ? name + 1 : library, "libpython3.%d", &minor) == 1 ? minor : -1;
}

/* Fills the home and search path the user left empty from the standard library
 * beside python->library; 0 when it is there (os.py and encodings: without
 * them Py_InitializeEx aborts the process). */
static int beside_library(struct python_location *python)
{
    int minor = minor_of_library(python->library);
    char directory[PATH_MAX], candidate[PATH_MAX + 32], stdlib[PATH_MAX];
    snprintf(directory, sizeof directory, "%s", python->library);
    char *slash = strrchr(directory, '/');
    if (minor < 0 || !slash)
        return -1;
    *slash = '\0';
    for (int up = 0; up < 2; up++) {
        snprintf(candidate, sizeof candidate, "%s%s/python3.%d", directory, up ? "/.." : "",
                 minor);
        if (!realpath(candidate, stdlib) || !exists(stdlib, "os.py") ||
            !exists(stdlib, "encodings/__init__.py"))
            continue;
        char lib[PATH_MAX], zip[PATH_MAX + 32];
        snprintf(lib, sizeof lib, "%s", stdlib);
        char *cut = strrchr(lib, '/');
        if (!cut || cut == lib) /* a standard library at /python3.X has no prefix */
            continue;
        *cut = '\0'; /* <prefix>/lib */
        if (!python->home[0]) {
            snprintf(python->home, sizeof python->home, "%s", lib);
            char *end = strrchr(python->home, '/');
            if (end)
                end[end == python->home] = '\0'; /* <prefix>, "/" for /lib */
        }
        if (!python->path[0]) {
            snprintf(zip, sizeof zip, "%s/python3%d.zip", lib, minor);
            int zipped = access(zip, R_OK) == 0;
            snprintf(python->path, sizeof python->path, "%s%s%s:%s/lib-dynload",
                     zipped ? zip : "", zipped ? ":" : "", stdlib, stdlib);
        }
        return 0;
    }
    return -1;
}

/* A candidate counts only if it loads and is a CPython: a damaged or foreign
 * libpython3.X (a 0-byte file) must not hide a working one further down. */
static int loads(const char *library)
{
    void *handle = dlopen(library, RTLD_LAZY | RTLD_LOCAL);
    int python = handle && dlsym(handle, "Py_IsInitialized") != NULL;
    if (handle)
        dlclose(handle);
    return python;
}

static int usable(struct python_location *python, const char *library)
{
    memset(python, 0, sizeof *python);
    snprintf(python->library, sizeof python->library, "%s", library);
    return access(library, R_OK) == 0 && beside_library(python) == 0 && loads(library);
}

/* ld.so.cache, read once per search and only up to a size no real cache nears. */
#define MOST_CACHE (16L << 20)
struct linker_cache {
    char *text;
    long size;
};

static void read_linker_cache(struct linker_cache *cache)
{
    cache->text = NULL, cache->size = 0;
    FILE *file = fopen(LINKER_CACHE, "rb");
    if (!file)
        return;
    long n = fseek(file, 0, SEEK_END) == 0 ? ftell(file) : -1;
    if (n > 0 && n <= MOST_CACHE && fseek(file, 0, SEEK_SET) == 0 &&
        (cache->text = malloc((size_t)n + 1))) {
        cache->size = (long)fread(cache->text, 1, (size_t)n, file);
        cache->text[cache->size] = '\0';
    }
    fclose(file);
}

/* Whatever its format version, ld.so.cache keeps each library's full path as a
 * NUL-terminated string: scanning for those needs none of its layout. */
static int in_linker_cache(const char *name, const struct linker_cache *linker,
                           struct python_location *found)
{
    const char *cache = linker->text;
    long n = linker->size;
    if (!cache)
        return -1;
    int result = -1;
    size_t length = strlen(name);
    for (long i = 0; i < n && result; i += (long)strlen(cache + i) + 1) {
        const char *entry = cache + i;
        size_t size = strlen(entry);
        if (entry[0] == '/' && size > length && entry[size - length - 1] == '/' &&
            strcmp(entry + size - length, name) == 0 && usable(found, entry))
            result = 0;
    }
    return result;
}

static int on_machine(int minor, const struct linker_cache *linker,
                      struct python_location *found)
{
    char name[32], library[PATH_MAX];
    snprintf(name, sizeof name, "libpython3.%d.so.1.0", minor);
    for (size_t i = 0; i < N_DIRECTORIES; i++) {
        snprintf(library, sizeof library, "%s/%s", LIBRARY_DIRECTORIES[i], name);
        if (usable(found, library))
            return 0;
    }
    return in_linker_cache(name, linker, found);
}

static int find(const struct runtime_record *record, struct python_location *found,
                char *error, size_t size)
{
    if (record->user.library[0]) {
        *found = record->user;
        if ((found->home[0] && found->path[0]) || beside_library(found) == 0)
            return 0;
        snprintf(error, size, "$" ENV_LIBRARY " names %s, but its standard library is not "
                 "beside it (<prefix>/lib/python3.X with os.py): set $" ENV_HOME " and $"
                 ENV_PATH " too", found->library);
        return -1;
    }
    *found = record->build;
    if (found->library[0] && access(found->library, R_OK) == 0 &&
        ((found->home[0] && found->path[0]) || beside_library(found) == 0))
        return 0;
    struct linker_cache linker;
    read_linker_cache(&linker);
    int result = on_machine(record->build_minor, &linker, found);
    for (int minor = NEWEST_MINOR; result && minor >= record->minimum_minor; minor--)
        if (minor != record->build_minor)
            result = on_machine(minor, &linker, found);
    free(linker.text);
    if (result == 0)
        return 0;
    char directories[1024] = "";
    for (size_t i = 0; i < N_DIRECTORIES; i++) {
        size_t used = strlen(directories);
        snprintf(directories + used, sizeof directories - used, "%s, ", LIBRARY_DIRECTORIES[i]);
    }
    snprintf(error, size, "no Python for this FMU: found no CPython 3.%d to 3.%d "
             "(libpython3.X.so.1.0 with its standard library at <prefix>/lib/python3.X) in "
             "%s" LINKER_CACHE "%s%s%s; " FIX_HINT, record->minimum_minor, NEWEST_MINOR,
             directories, record->build.library[0] ? " nor the build's " : "",
             record->build.library, record->build.library[0] ? " (gone)" : "");
    return -1;
}

/* The user's home and path apply to whichever Python is found: a path that
 * adds a folder of modules is enough where the machine's Python lacks them. */
int find_python(const struct runtime_record *record, struct python_location *found,
                char *error, size_t size)
{
    if (find(record, found, error, size))
        return -1;
    if (record->user.home[0])
        snprintf(found->home, sizeof found->home, "%s", record->user.home);
    if (record->user.path[0])
        snprintf(found->path, sizeof found->path, "%s", record->user.path);
    return 0;
}

int locate_loaded(const struct runtime_record *record, const char *library,
                  struct python_location *found, char *error, size_t size)
{
    memset(found, 0, sizeof *found);
    snprintf(found->library, sizeof found->library, "%s", library);
    snprintf(found->home, sizeof found->home, "%s", record->user.home);
    snprintf(found->path, sizeof found->path, "%s", record->user.path);
    if ((found->home[0] && found->path[0]) || beside_library(found) == 0)
        return 0;
    snprintf(error, size, "this process already holds %s, not running: the one Python the "
             "runtime may start here, but its standard library is not beside it (<prefix>/lib/"
             "python3.X with os.py): set $" ENV_HOME " and $" ENV_PATH, library);
    return -1;
}
