/* Where PyConfig keeps the few fields the runtime sets, per CPython minor.
 *
 * The runtime uses no Python headers (one binary starts 3.10 to 3.13), so it
 * cannot take these from <cpython/initconfig.h>; the table is checked against
 * each minor's headers by tests/unit/test_config_layout.py.  `size` is
 * sizeof(PyConfig) of a release build (a debug build adds fields after these). */
#ifndef CARDAN_JOINT_CONFIG_LAYOUT_H
#define CARDAN_JOINT_CONFIG_LAYOUT_H

#include <stddef.h>

struct config_layout {
    int minor;
    size_t size, home, module_search_paths_set, module_search_paths, site_import,
        install_signal_handlers;
};

static const struct config_layout CONFIG_LAYOUTS[] = {
    {10, 392, 256, 272, 280, 152, 16},
    {11, 424, 280, 296, 304, 168, 16},
    {12, 432, 288, 304, 312, 176, 16},
    {13, 448, 296, 312, 320, 176, 16},
};
#define N_CONFIG_LAYOUTS (sizeof CONFIG_LAYOUTS / sizeof *CONFIG_LAYOUTS)
/* Room for PyConfig of every minor above, debug builds included. */
#define CONFIG_ROOM 2048
/* PyPreConfig: the same in 3.10-3.13 (Linux). */
#define PRECONFIG_SIZE 40
#define PRECONFIG_UTF8_MODE 28

#endif
