/* Messages of an instance to its host, the same for FMI 2.0 and FMI 3.0: the
 * slave always logs here with logging on, warnings and refusals reach the
 * host's logger whether or not it asked for debug logging, and the status a
 * call returns is the worst one logged during it.  Only the call into the
 * host's logger differs between the versions: to_host() (loader.c, fmi3_loader.c). */
#define _GNU_SOURCE
#include "instance.h"

#include <dlfcn.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

static const char *const STATUS_NAMES[] = {"OK", "Warning", "Discard", "Error", "Fatal", "Pending"};
static const char *const STATUS_CATEGORIES[] = {
    "logAll", "logStatusWarning", "logStatusDiscard", "logStatusError", "logStatusFatal", "logAll"};

static int category_enabled(const struct instance *in, const char *category)
{
    if (!in->logging_on)
        return 0;
    if (in->n_categories == 0 || strcmp(category, "logAll") == 0)
        return 1;
    for (size_t i = 0; i < in->n_categories; i++)
        if (strcmp(in->categories[i], category) == 0 || strcmp(in->categories[i], "logAll") == 0)
            return 1;
    return 0;
}

void report(struct instance *in, fmi2Status status, const char *category, const char *text)
{
    unsigned index = status <= fmi2Pending ? (unsigned)status : (unsigned)fmi2Fatal;
    if (status > in->worst)
        in->worst = status;
    if (!category || !*category)
        category = STATUS_CATEGORIES[index];
    int important = status != fmi2OK && status != fmi2Pending;
    if (!important && !category_enabled(in, category))
        return;
    int to_logger = (in->logging_on || !in->shared_proxy) && to_host(in, status, category, text);
    if (in->echo_stderr || (!to_logger && important))
        fprintf(stderr, "[%s %s] %s: %s\n", in->model, in->name, STATUS_NAMES[index], text);
}

void reportf(struct instance *in, fmi2Status status, const char *format, ...)
{
    char text[1024];
    va_list args;
    va_start(args, format);
    vsnprintf(text, sizeof text, format, args);
    va_end(args);
    report(in, status, NULL, text);
}

/* FMPy's logger proxy (fmpy/logging) keeps ONE target for the whole process:
 * the logger of the last callbacks it wrapped, which simulate_fmu frees when
 * it returns. Calling it for an instance whose host did not turn logging on
 * may jump into freed memory, so such messages go to stderr instead. */
int is_shared_proxy(void *logger)
{
    Dl_info where;
    return logger && dladdr(logger, &where) && where.dli_fname &&
           strstr(where.dli_fname, "/fmpy/logging/");
}
