"""Ctrl-C during a run, taken between steps rather than inside the FMU.

The FMU's Python code runs in the host's interpreter: Python's default SIGINT
handler raises KeyboardInterrupt wherever the main thread happens to be, most
often inside the FMU's step, where the FMU's runtime turns it into a failed
step ("the slave's fast_step failed") and the run looks refused. While a run
holds `interrupt_between_steps`, a first Ctrl-C only records the request: the
run loop sees it after the step in progress, ends the run cleanly and raises
`SimulationInterrupted` (a KeyboardInterrupt) with the time reached. A second
Ctrl-C raises at once, as usual. Only the main thread receives signals, and a
handler the host program installed itself is left alone: then nothing changes.
"""

import signal
import threading
from collections.abc import Iterator
from contextlib import contextmanager

import numpy as np


class SimulationInterrupted(KeyboardInterrupt):
    """Ctrl-C ended the run at `time` (s); `result` holds the run up to there."""

    def __init__(self, time: float, result: np.ndarray) -> None:
        super().__init__(f"interrupted at t = {time:.6g} s")
        self.time = time
        self.result = result


class InterruptRequest:
    """Whether Ctrl-C was pressed while the run held the handler."""

    requested = False

    def _handle(self, signum, frame) -> None:
        if self.requested:  # a second Ctrl-C: the user does not want to wait for the step
            raise KeyboardInterrupt
        self.requested = True


@contextmanager
def interrupt_between_steps() -> Iterator[InterruptRequest]:
    """Hold Ctrl-C for the block (main thread, Python's own handler only)."""
    request = InterruptRequest()
    if (
        threading.current_thread() is not threading.main_thread()
        or signal.getsignal(signal.SIGINT) is not signal.default_int_handler
    ):
        yield request
        return
    signal.signal(signal.SIGINT, request._handle)
    try:
        yield request
    finally:
        signal.signal(signal.SIGINT, signal.default_int_handler)
