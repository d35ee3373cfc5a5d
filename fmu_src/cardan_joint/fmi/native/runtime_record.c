/* Reads resources/python_runtime.txt, the build's record of its Python.
 *
 *     # comment
 *     version = 3.11
 *     library = /path/libpython3.11.so.1.0
 *     home = /path                   (sys.base_prefix)
 *     executable = /path/bin/python3.11
 *     path = /path/lib/python3.11    (one line per entry, in order)
 *
 * Environment variables named in loader.h override library, home and path, for
 * an FMU moved to a machine where the Python lives elsewhere.
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
        if (c[0] == '%' && isxdigit((unsigned char)c[1]) && isxdigit((unsigned char)c[2])) {
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

static void append_path(struct runtime_record *record, const char *entry)
{
    size_t used = strlen(record->path);
    snprintf(record->path + used, sizeof record->path - used, "%s%s", used ? ":" : "", entry);
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
    char line[8192];
    while (fgets(line, sizeof line, file)) {
        char *text = trim(line), *equals = strchr(text, '=');
        if (!*text || *text == '#' || !equals)
            continue;
        *equals = '\0';
        char *key = trim(text), *value = trim(equals + 1);
        if (strcmp(key, "version") == 0)
            copy(record->version, sizeof record->version, value);
        else if (strcmp(key, "library") == 0)
            copy(record->library, sizeof record->library, value);
        else if (strcmp(key, "home") == 0)
            copy(record->home, sizeof record->home, value);
        else if (strcmp(key, "executable") == 0)
            copy(record->executable, sizeof record->executable, value);
        else if (strcmp(key, "path") == 0)
            append_path(record, value);
    }
    fclose(file);
    const char *library = getenv(ENV_LIBRARY), *home = getenv(ENV_HOME), *path = getenv(ENV_PATH);
    if (library && *library)
        copy(record->library, sizeof record->library, library);
    if (home && *home)
        copy(record->home, sizeof record->home, home);
    if (path && *path)
        copy(record->path, sizeof record->path, path);
    if (!record->version[0]) {
        snprintf(error, size, "%s has no 'version' line: the FMU is incomplete, rebuild it", name);
        return -1;
    }
    return 0;
}

/* Fixed parameters from modelDescription.xml (beside resources/): FMI allows
 * setting them only before fmi2ExitInitializationMode, whatever state the slave
 * was restored to. A light scan: the file is the build's own output. */
int read_fixed_parameters(const char *resources, struct fixed_parameters *fixed)
{
    char name[4200];
    snprintf(name, sizeof name, "%s/../modelDescription.xml", resources);
    FILE *file = fopen(name, "r");
    if (!file)
        return -1;
    static char xml[1 << 20];
    size_t n = fread(xml, 1, sizeof xml - 1, file);
    fclose(file);
    xml[n] = '\0';
    fixed->count = 0;
    for (char *v = strstr(xml, "<ScalarVariable"); v && fixed->count < MAX_FIXED;
         v = strstr(v + 1, "<ScalarVariable")) {
        char *end = strchr(v, '>'), *reference = strstr(v, "valueReference=\"");
        char *variability = strstr(v, "variability=\"fixed\""), *label = strstr(v, " name=\"");
        if (!end || !reference || !label || !variability || variability > end)
            continue;
        struct fixed_parameter *p = &fixed->parameters[fixed->count];
        if (sscanf(reference, "valueReference=\"%u", &p->vr) == 1 &&
            sscanf(label, " name=\"%63[^\"]", p->name) == 1)
            fixed->count++;
    }
    return 0;
}
