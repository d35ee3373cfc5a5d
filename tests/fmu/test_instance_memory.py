"""Issue 24 item 2: no per-instance memory left behind after free: 2,000 more
instantiate/free cycles (each initialized and stepped) grow a C host's peak memory
by less than 1 KB per cycle, FMI 2.0 and 3.0. FMI 2.0 here, a check in the
developer's loop; FMI 3.0 in tests/system/test_long_runs.py (one runtime serves both)."""

import os
import subprocess

FEW, MANY = 200, 2200


def peak_kib(host, folder, cycles: int) -> int:
    """The host's peak resident memory (KiB) after `cycles` cycles."""
    process = subprocess.Popen(
        [str(host), "cycles", str(folder), str(cycles)],
        env={"PATH": "/usr/bin:/bin"},
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
    )
    _, status, usage = os.wait4(process.pid, 0)
    out = process.stdout.read().decode()
    process.stdout.close(), process.stderr.close()
    assert os.waitstatus_to_exitcode(status) == 0 and f"cycles {cycles} ok" in out, out
    return usage.ru_maxrss


def cycles_leave_less_than_a_kilobyte_each(request, version: int) -> None:
    """MANY cycles against FEW of the `version` FMU in the C host: < 1 KB each."""
    host = request.getfixturevalue("c_host3" if version == 3 else "c_host")
    folder = request.getfixturevalue("fmi3_unzipped" if version == 3 else "unzipped_fmu")
    growth = peak_kib(host, folder, MANY) - peak_kib(host, folder, FEW)
    per_cycle = growth * 1024 / (MANY - FEW)
    assert per_cycle < 1024, f"{per_cycle:.0f} bytes per cycle"


def test_two_thousand_cycles_leave_less_than_a_kilobyte_each(request):
    cycles_leave_less_than_a_kilobyte_each(request, 2)
