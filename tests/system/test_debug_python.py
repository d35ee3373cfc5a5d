"""Issue 33 item 2: on a debug CPython (Debian's python3.11-dbg, libpython3.11d,
whose allocator checks the GIL through CPython's own thread slot), host threads
that first entered Python in the runtime end cleanly: ten concurrent starts of
FMI 2.0 and 3.0 FMUs, every one equal to the serial run. The runtime ends each
such thread's Python state before glibc empties that slot (python_runtime.c)."""

from pathlib import Path

from test_concurrent_start import started_together

DEBUG_LIBRARY = Path("/usr/lib/x86_64-linux-gnu/libpython3.11d.so.1.0")
RUNS = 10


def test_threads_that_entered_a_debug_python_exit_cleanly_ten_of_ten(
    concurrent_host, unzipped_fmu, propshaft_unzipped, fmi3_unzipped
):
    assert DEBUG_LIBRARY.is_file(), (
        f"{DEBUG_LIBRARY} is missing: apt-get install python3.11-dbg (the README's set-up line)"
    )
    folders = (unzipped_fmu, propshaft_unzipped, fmi3_unzipped)
    python = {"CARDAN_JOINT_FMU_PYTHON_LIBRARY": str(DEBUG_LIBRARY)}
    started_together(concurrent_host, folders, RUNS, python)
