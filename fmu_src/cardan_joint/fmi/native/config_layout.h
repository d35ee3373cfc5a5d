/* Every CPython minor the runtime starts in a host without Python, and what
 * differs between them: the one table a new minor is added to (docs/runtime.md,
 * "Adding a CPython minor"); discovery looks for these minors, newest first.
 *
 * Up to 3.13 the runtime fills a PyConfig struct, and one binary starts them
 * all without Python headers: the offsets of the few fields it sets come from
 * here, checked against each minor's headers by tests/unit/test_config_layout.py
 * (`size` is sizeof(PyConfig) of a release build; a debug build adds fields
 * after these).  From 3.14 on PEP 741's PyInitConfig API sets the same options
 * by name: such a minor is one line with no offsets. */
#ifndef CARDAN_JOINT_CONFIG_LAYOUT_H
#define CARDAN_JOINT_CONFIG_LAYOUT_H

#include <stddef.h>

enum start_api {
    CONFIG_STRUCT, /* PyConfig_InitIsolatedConfig + Py_InitializeFromConfig (3.8-3.13) */
    INIT_CONFIG,   /* PyInitConfig_Create + Py_InitializeFromInitConfig (PEP 741, 3.14 on) */
};

struct cpython_minor {
    int minor;
    enum start_api api;
    /* CONFIG_STRUCT only: PyConfig's size and the offsets of the fields set */
    size_t size, home, module_search_paths_set, module_search_paths, site_import,
        install_signal_handlers;
};

static const struct cpython_minor CPYTHON_MINORS[] = {
    {10, CONFIG_STRUCT, 392, 256, 272, 280, 152, 16},
    {11, CONFIG_STRUCT, 424, 280, 296, 304, 168, 16},
    {12, CONFIG_STRUCT, 432, 288, 304, 312, 176, 16},
    {13, CONFIG_STRUCT, 448, 296, 312, 320, 176, 16},
    {14, INIT_CONFIG, 0, 0, 0, 0, 0, 0},
    {15, INIT_CONFIG, 0, 0, 0, 0, 0, 0},
};
#define N_CPYTHON_MINORS (sizeof CPYTHON_MINORS / sizeof *CPYTHON_MINORS)
#define OLDEST_MINOR (CPYTHON_MINORS[0].minor)
#define NEWEST_MINOR (CPYTHON_MINORS[N_CPYTHON_MINORS - 1].minor)
/* Room for PyConfig of every CONFIG_STRUCT minor above, debug builds included. */
#define CONFIG_ROOM 2048
/* PyPreConfig: the same in 3.10-3.13 (Linux). */
#define PRECONFIG_SIZE 40
#define PRECONFIG_UTF8_MODE 28

#endif
