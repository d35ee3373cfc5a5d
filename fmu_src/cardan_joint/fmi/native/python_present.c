/* The libpythons already loaded in this process, in any scope: a host's own
 * (loaded and not started, finalized, or a plugin's RTLD_LOCAL one) is
 * invisible to dlsym(RTLD_DEFAULT), but every loaded object is listed by
 * dl_iterate_phdr.  python_runtime.c joins or starts such a one, or refuses
 * several by name: never a second libpython beside them. */
#define _GNU_SOURCE
#include "loader.h"

#include <link.h>
#include <stdio.h>
#include <string.h>

struct present {
    int count;
    char *one, *names;
    size_t one_size, names_size;
};

static int visit(struct dl_phdr_info *info, size_t size, void *data)
{
    (void)size;
    struct present *present = data;
    const char *path = info->dlpi_name, *slash = path ? strrchr(path, '/') : NULL;
    const char *name = slash ? slash + 1 : path;
    int minor;
    /* libpython3.X.so*, libpython3.Xd.so*, libpython3.Xt.so*; not libpython3.so, the
     * stable ABI's shim, which only forwards to one of them */
    if (!name || sscanf(name, "libpython3.%d", &minor) != 1 || !strstr(name, ".so"))
        return 0;
    if (present->count++ == 0)
        snprintf(present->one, present->one_size, "%s", path);
    size_t used = strlen(present->names);
    snprintf(present->names + used, present->names_size - used, "%s%s", used ? ", " : "", path);
    return 0;
}

int loaded_pythons(char *one, size_t one_size, char *names, size_t names_size)
{
    struct present present = {0, one, names, one_size, names_size};
    one[0] = names[0] = '\0';
    dl_iterate_phdr(visit, &present);
    return present.count;
}
