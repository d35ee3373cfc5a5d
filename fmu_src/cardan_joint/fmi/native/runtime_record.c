/* Reads resources/python_runtime.txt, what the FMU needs of a Python.
 *
 *     # comment
 *     minimum = 3.10                 (the oldest CPython the FMU's code runs on)
 *     version = 3.11                 (the build's; preferred on a machine with several)
 *     library = /path/libpython3.11.so.1.0   \  optional hint: the build's Python,
 *     home = /path                            > tried first where it still exists;
 *     path = /path/lib/python3.11            /  one 'path' line per entry, in order
 *
 * The environment variables named in loader.h name the user's Python instead.
 */
#include "loader.h"

#include <ctype.h>
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int hex(int c)
{
    return isdigit(c) ? c - '0' : tolower(c) - 'a' + 10;
}

int resources_folder(const char *location, char *folder, size_t size)
{
    if (!location)
        return -1;
    /* Only a URI is percent-encoded: FMI 3.0's resourcePath is a plain path, in
     * which a folder named x%41y is just that. */
    int uri = strncmp(location, "file:", 5) == 0;
    if (strncmp(location, "file://", 7) == 0) {
        location += 7;
        if (strncmp(location, "localhost/", 10) == 0)
            location += 9;
    } else if (strncmp(location, "file:", 5) == 0) {
        location += 5;
    }
    size_t n = 0;
    for (const char *c = location; *c; c++) {
        if (n + 1 >= size)
            return -1;
        if (uri && c[0] == '%' && isxdigit((unsigned char)c[1]) &&
            isxdigit((unsigned char)c[2])) {
            folder[n++] = (char)(hex((unsigned char)c[1]) * 16 + hex((unsigned char)c[2]));
            c += 2;
        } else {
            folder[n++] = *c;
        }
    }
    while (n > 1 && folder[n - 1] == '/')
        n--;
    folder[n] = '\0';
    return 0;
}

static char *trim(char *text)
{
    while (isspace((unsigned char)*text))
        text++;
    char *end = text + strlen(text);
    while (end > text && isspace((unsigned char)end[-1]))
        *--end = '\0';
    return text;
}

static void copy(char *field, size_t size, const char *value)
{
    snprintf(field, size, "%s", value);
}

static void append_path(struct python_location *python, const char *entry)
{
    size_t used = strlen(python->path);
    snprintf(python->path + used, sizeof python->path - used, "%s%s", used ? ":" : "", entry);
}

/* "3.11" -> 11; -1 for anything that is not a Python 3 version. */
static int minor_of(const char *version)
{
    int major, minor;
    char end;
    return sscanf(version, "%d.%d%c", &major, &minor, &end) == 2 && major == 3 && minor >= 0
        ? minor : -1;
}

static void from_environment(const char *name, char *field, size_t size)
{
    const char *value = getenv(name);
    if (value && *value)
        copy(field, size, value);
}

int read_runtime_record(const char *resources, struct runtime_record *record,
                        char *error, size_t size)
{
    memset(record, 0, sizeof *record);
    char name[4200];
    snprintf(name, sizeof name, "%s/" RUNTIME_RECORD, resources);
    FILE *file = fopen(name, "r");
    if (!file) {
        snprintf(error, size, "cannot read %s (%s): the FMU is incomplete, rebuild it",
                 name, strerror(errno));
        return -1;
    }
    char line[8192], minimum[16] = "", version[16] = "";
    while (fgets(line, sizeof line, file)) {
        char *text = trim(line), *equals = strchr(text, '=');
        if (!*text || *text == '#' || !equals)
            continue;
        *equals = '\0';
        char *key = trim(text), *value = trim(equals + 1);
        struct python_location *build = &record->build;
        if (strcmp(key, "minimum") == 0)
            copy(minimum, sizeof minimum, value);
        else if (strcmp(key, "version") == 0)
            copy(version, sizeof version, value);
        else if (strcmp(key, "library") == 0)
            copy(build->library, sizeof build->library, value);
        else if (strcmp(key, "home") == 0)
            copy(build->home, sizeof build->home, value);
        else if (strcmp(key, "path") == 0)
            append_path(build, value);
    }
    fclose(file);
    struct python_location *user = &record->user;
    from_environment(ENV_LIBRARY, user->library, sizeof user->library);
    from_environment(ENV_HOME, user->home, sizeof user->home);
    from_environment(ENV_PATH, user->path, sizeof user->path);
    record->minimum_minor = minor_of(minimum);
    record->build_minor = version[0] ? minor_of(version) : record->minimum_minor;
    if (record->minimum_minor < 0 || record->build_minor < 0) {
        snprintf(error, size, "%s has no valid 'minimum' (%s) or 'version' (%s) line: the FMU "
                 "is incomplete, rebuild it", name, minimum, version);
        return -1;
    }
    return 0;
}

/* The build's variable record (resources/VARIABLES_RECORD), one row per
 * variable: both FMI versions read it, each keeping what it needs.  Not
 * modelDescription.xml: hosts need not extract it (FMPy extracts resources/ and
 * binaries/ only), and a guard that silently turns off is no guard. */
int read_variable_record(const char *resources, int (*keep)(const struct record_row *, void *),
                         void *kept, int most, char *error, size_t size)
{
    char name[4200], line[256];
    snprintf(name, sizeof name, "%s/" VARIABLES_RECORD, resources);
    FILE *file = fopen(name, "r");
    if (!file) {
        snprintf(error, size, "cannot read %s (%s): the FMU is incomplete, rebuild it", name,
                 strerror(errno));
        return -1;
    }
    int line_number = 0, ok = 1, rows = 0;
    while (ok && fgets(line, sizeof line, file)) {
        line_number++;
        if (line[0] == '#' || line[0] == '\n')
            continue;
        struct record_row row;
        char end = 0;
        /* A whole line or none: a row cut short by a truncated file is refused. */
        ok = sscanf(line, "%u %15s %zu %d %63s%c", &row.vr, row.type, &row.size, &row.fixed,
                    row.name, &end) == 6 && end == '\n' && (row.fixed == 0 || row.fixed == 1) &&
             keep(&row, kept);
        rows++;
    }
    fclose(file);
    if (ok && rows == 0) {
        snprintf(error, size, "%s names no variable: the FMU is incomplete, rebuild it", name);
        return -1;
    }
    if (!ok)
        snprintf(error, size, "%s, line %d: not 'valueReference type size fixed name' "
                              "(at most %d kept): rebuild the FMU", name, line_number, most);
    return ok ? 0 : -1;
}

static int keep_fixed(const struct record_row *row, void *kept)
{
    struct fixed_parameters *fixed = kept;
    if (!row->fixed)
        return 1;
    if (fixed->count >= MAX_FIXED)
        return 0;
    struct fixed_parameter *p = &fixed->parameters[fixed->count++];
    p->vr = row->vr;
    snprintf(p->name, sizeof p->name, "%s", row->name);
    return 1;
}

/* FMI allows setting fixed parameters only before fmi2ExitInitializationMode,
 * whatever state the slave was restored to. */
int read_fixed_parameters(const char *resources, struct fixed_parameters *fixed,
                          char *error, size_t size)
{
    fixed->count = 0;
    return read_variable_record(resources, keep_fixed, fixed, MAX_FIXED, error, size);
}

struct named {
    unsigned vr;
    char *name;
    size_t size;
    int found;
};

static int keep_name(const struct record_row *row, void *kept)
{
    struct named *named = kept;
    if (row->vr == named->vr && !named->found) {
        snprintf(named->name, named->size, "%s", row->name);
        named->found = 1;
    }
    return 1;
}

/* For messages: the name of the variable with value reference vr; 0 if found. */
int variable_name(const char *resources, unsigned vr, char *name, size_t size)
{
    char error[512];
    struct named named = {vr, name, size, 0};
    int read = read_variable_record(resources, keep_name, &named, 1 << 20, error, sizeof error);
    return read == 0 && named.found ? 0 : -1;
}
