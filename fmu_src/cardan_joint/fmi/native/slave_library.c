/* Loading the pythonfmu binary the loader stands in front of (FMI 2.0 and 3.0). */
#define _GNU_SOURCE
#include "instance.h"

#include <dlfcn.h>
#include <limits.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static void (*finalize_slave)(void);

/* pythonfmu 0.7.0 (and pythonfmu3 0.3.4, same code) resets its static
 * shared_ptr<PyState> twice at exit: once in the destructor registered with
 * __cxa_atexit when its binary is loaded, then in its __attribute__((destructor)),
 * which frees it again ("free(): corrupted unsorted chunks").  This handler,
 * registered after that load, runs first: the exported finalizePythonInterpreter
 * empties the pointer before it releases it, so both later resets find nothing
 * to free. */
static void empty_slave_state_at_exit(void)
{
    if (finalize_slave)
        finalize_slave();
}

/* <MODEL_IDENTIFIER><suffix> beside this file, loaded once; `resolve` fills the
 * caller's table of its entry points. */
int load_slave_library(const char *suffix, int (*resolve)(void *, char *, size_t), char *error,
                       size_t size)
{
    static pthread_mutex_t lock = PTHREAD_MUTEX_INITIALIZER;
    static void *loaded;
    int result = 0;
    pthread_mutex_lock(&lock);
    if (!loaded) {
        Dl_info self = {0};
        char path[PATH_MAX];
        if (!dladdr((void *)&load_slave_library, &self) || !self.dli_fname)
            self.dli_fname = "";
        snprintf(path, sizeof path, "%s", self.dli_fname);
        char *slash = strrchr(path, '/');
        snprintf(slash ? slash + 1 : path, sizeof path - (size_t)(slash ? slash + 1 - path : 0),
                 "%s%s", MODEL_IDENTIFIER, suffix);
        void *handle = dlopen(path, RTLD_NOW | RTLD_LOCAL);
        if (!handle) {
            snprintf(error, size, "cannot load pythonfmu's binary: %s", dlerror());
            result = -1;
        } else if (resolve(handle, error, size)) {
            dlclose(handle);
            result = -1;
        } else {
            finalize_slave = (void (*)(void))dlsym(handle, "finalizePythonInterpreter");
            atexit(empty_slave_state_at_exit);
            loaded = handle;
        }
    }
    pthread_mutex_unlock(&lock);
    return result;
}

