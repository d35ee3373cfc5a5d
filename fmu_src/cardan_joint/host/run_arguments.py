"""The arguments of a run, checked once for the command line and the Python API
alike: stop time, communication step (output interval), and the run's size
against where its result goes (memory for `simulate`, the disk for a CSV
streamed by `simulate_to_csv`), before the first step. Each mistake is a
`UsageError` naming the value and the limit; a run too large names its size.
"""

import math
import numbers
import os
import shutil
from dataclasses import dataclass
from pathlib import Path

from ..names import UsageError

# One recorded row in FMPy's recorder (a tuple of Python floats) and then in
# its NumPy result: a tuple header, a pointer and a float object per value,
# and the array's 8 bytes per value. Measured by tests/unit/test_run_arguments.py.
ROW_BYTES, VALUE_BYTES = 64, 48
# One value in a CSV: up to 24 characters (-1.2345678901234567e-100) and a comma.
CSV_VALUE_BYTES = 25


class RunTooLargeError(UsageError):
    """A run whose result would not fit where it goes; the message names its size."""


def size_text(count: float) -> str:
    """Bytes in the largest unit that keeps them >= 1 (kB, MB, ... as powers of 1000)."""
    for unit in ("B", "kB", "MB", "GB", "TB", "PB"):
        if count < 1000 or unit == "PB":
            return f"{count:.3g} {unit}"
        count /= 1000
    raise AssertionError("unreachable")


@dataclass(frozen=True)
class RunLength:
    """How long a run is: `steps` communication steps, `rows` recorded rows."""

    stop_time: float
    step: float
    steps: int

    @property
    def rows(self) -> int:
        return self.steps + 1


def run_length(stop_time: float, step: float) -> RunLength:
    """The run's length; UsageError unless 0 < step <= stop time, both finite."""
    if not (isinstance(stop_time, numbers.Real) and math.isfinite(stop_time) and stop_time > 0):
        raise UsageError(f"stop time {stop_time!r} s must be a finite number > 0")
    if not (isinstance(step, numbers.Real) and math.isfinite(step) and 0 < step <= stop_time):
        raise UsageError(
            f"output interval (communication step) {step!r} s must be a number > 0 "
            f"and at most the stop time {stop_time!r} s"
        )
    return RunLength(float(stop_time), float(step), max(1, round(stop_time / step)))


def available_memory() -> float | None:
    """Bytes of memory available to a new allocation (Linux's MemAvailable), or None."""
    try:
        with open("/proc/meminfo") as stream:
            for line in stream:
                if line.startswith("MemAvailable:"):
                    return float(line.split()[1]) * 1024
    except OSError:
        pass
    try:
        return float(os.sysconf("SC_AVPHYS_PAGES") * os.sysconf("SC_PAGE_SIZE"))
    except (ValueError, OSError, AttributeError):
        return None


def _too_large(length: RunLength, values: int, needed: float, where: str, free: float) -> str:
    return (
        f"a run of {length.steps:,} steps of {length.step:g} s to {length.stop_time:g} s "
        f"records {length.rows:,} rows of {values} values: about {size_text(needed)} "
        f"{where}, more than the {size_text(free)} available; take a longer step, a "
        f"shorter stop time or fewer variables"
    )


def check_memory(length: RunLength, values: int, free: float | None = None) -> None:
    """RunTooLargeError if the recorded rows (`values` each, time included) would
    not fit in the memory available (`free` bytes, default: this machine's)."""
    free = available_memory() if free is None else free
    needed = length.rows * (ROW_BYTES + VALUE_BYTES * values)
    if free is not None and needed > free:
        raise RunTooLargeError(
            _too_large(length, values, needed, "of memory", free)
            + " (or stream it to a file: simulate_to_csv, `cardan-joint simulate`)"
        )


def check_disk(length: RunLength, values: int, path: Path, free: float | None = None) -> None:
    """RunTooLargeError if a CSV of the run (`values` columns) would not fit on
    the file system that holds `path` (`free` bytes, default: measured)."""
    if free is None:
        folder = Path(path).resolve().parent
        while not folder.exists():
            folder = folder.parent
        free = float(shutil.disk_usage(folder).free)
    needed = length.rows * CSV_VALUE_BYTES * values
    if needed > free:
        raise RunTooLargeError(_too_large(length, values, needed, f"as CSV ({path})", free))
