"""Ctrl-C (and SIGTERM, SIGHUP) during a run, taken between steps rather than inside the FMU.

The FMU's Python code runs in the host's interpreter: Python's default SIGINT
handler raises KeyboardInterrupt wherever the main thread happens to be, most
often inside the FMU's step, where the FMU's runtime turns it into a failed
step ("the slave's do_step was interrupted") and the run looks refused. While a run
holds `interrupt_between_steps`, a first stop signal only records the request:
the run loop sees it after the step in progress, ends the run cleanly and
raises `SimulationInterrupted` (a KeyboardInterrupt) with the time reached. A
second one raises at once, as usual. An `FmuInstance` holds `STEP_INTERRUPTS`
while it is open: a signal during a call into its FMU is raised when the call
is over, one between two calls at once, as Python's own handler does.

SIGTERM and SIGHUP, whose default ends the process on the spot (leaving a half
written file and the unzipped FMU behind), are taken the same way and raise
`Stopped` (a KeyboardInterrupt naming the signal). Only the main thread
receives signals, and a handler the host program installed itself is left
alone: then nothing changes for that signal.
"""

import signal
import threading
from collections.abc import Iterator
from contextlib import ExitStack, contextmanager
from typing import Any

import numpy as np

STOP_SIGNALS = tuple(
    getattr(signal, name) for name in ("SIGINT", "SIGTERM", "SIGHUP") if hasattr(signal, name)
)


def signal_name(signum: int) -> str:
    return signal.Signals(signum).name


class Stopped(KeyboardInterrupt):
    """SIGTERM or SIGHUP, raised where Ctrl-C raises KeyboardInterrupt."""

    def __init__(self, signum: int) -> None:
        super().__init__(signal_name(signum))
        self.signum = signum


def raise_stop(signum: int, frame: Any = None) -> None:
    """Raise what a stop signal means: KeyboardInterrupt for SIGINT, else Stopped."""
    if signum == signal.SIGINT:
        raise KeyboardInterrupt
    raise Stopped(signum)


def interrupted(interrupt: BaseException) -> str:
    """ "interrupted", naming the signal unless it was Ctrl-C's."""
    signum = getattr(interrupt, "signum", signal.SIGINT)
    return "interrupted" if signum == signal.SIGINT else f"interrupted by {signal_name(signum)}"


def exit_status(interrupt: BaseException) -> int:
    """A shell's exit status for a process ended by this interrupt: 128 + the signal."""
    return 128 + getattr(interrupt, "signum", signal.SIGINT)


class SimulationInterrupted(KeyboardInterrupt):
    """A stop signal (`signum`, Ctrl-C's by default) ended the run at `time` (s);
    `result` holds the run up to there."""

    def __init__(self, time: float, result: np.ndarray, signum: int | None = None) -> None:
        super().__init__(f"interrupted at t = {time:.6g} s")
        self.time = time
        self.result = result
        self.signum = signal.SIGINT if signum is None else signum


class InterruptRequest:
    """Which stop signal came while the run held the handlers (`signum`, None if none).

    `holding`: whether a first signal now waits (False: it raises at once)."""

    signum: int | None = None
    holding = True

    @property
    def requested(self) -> bool:
        return self.signum is not None

    def _handle(self, signum, frame) -> None:
        if self.requested or not self.holding:  # a second one: the user does not want to wait
            raise_stop(signum)
        self.signum = signum

    def raise_requested(self) -> None:
        """Raise the signal that came while held, if any (once)."""
        if self.signum is not None:
            signum, self.signum = self.signum, None
            raise_stop(signum)


def _python_default(signum: int) -> Any:
    return signal.default_int_handler if signum == signal.SIGINT else signal.SIG_DFL


def _ours(handler: Any) -> bool:
    """Python's or this module's handler: one a run may replace for its length."""
    return handler is raise_stop or isinstance(getattr(handler, "__self__", None), InterruptRequest)


@contextmanager
def _handled(handler: Any) -> Iterator[None]:
    """`handler` for every stop signal whose handler is Python's own or this
    module's (main thread only), the earlier ones back after the block."""
    if threading.current_thread() is not threading.main_thread():
        yield
        return
    previous = {}
    for signum in STOP_SIGNALS:
        current = signal.getsignal(signum)
        if current is _python_default(signum) or _ours(current):
            previous[signum] = current
    for signum in previous:
        signal.signal(signum, handler)
    try:
        yield
    finally:
        for signum, earlier in previous.items():
            signal.signal(signum, earlier)


@contextmanager
def interrupt_between_steps() -> Iterator[InterruptRequest]:
    """Hold the stop signals for the block (main thread, Python's own handlers only)."""
    request = InterruptRequest()
    with _handled(request._handle):
        yield request


@contextmanager
def stop_signals_raise() -> Iterator[None]:
    """For a command's length: SIGTERM and SIGHUP raise `Stopped` wherever Ctrl-C
    would raise KeyboardInterrupt, so that the same clean-up runs."""
    with _handled(raise_stop):
        yield


class StepInterrupts:
    """The stop signals held to the end of an `FmuInstance`'s call into its FMU, while any
    instance is open (`acquire` at open, `release` at close)."""

    def __init__(self) -> None:
        self.request = InterruptRequest()
        self.request.holding = False
        self._users = 0
        self._handlers = ExitStack()

    def acquire(self) -> None:
        if self._users == 0:
            self._handlers.enter_context(_handled(self.request._handle))
        self._users += 1

    def release(self) -> None:
        self._users -= 1
        if self._users == 0:
            self.request.signum = None
            try:
                self._handlers.close()
            except ValueError:  # closed outside the main thread: signals cannot be set there
                pass


STEP_INTERRUPTS = StepInterrupts()
