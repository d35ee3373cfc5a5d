"""Watches: limits an engineer wants to hear of while the run goes on.

A model declares its watches as data, one row each (`Watch`): an output (a
glob such as `joint_*_life_consumed` names every joint's), the limit (a
parameter's name or a number) and what passing it means. The slave compiles
the rows against its variable table (`compile_watches`: output slots), reads
each limit when initialization ends (`arm`) and, after every taken step,
logs each output whose magnitude is past its limit, once (`passed`). No
physics step knows of them: the rows are plain data a generated step in C can
read as well.
"""

import math
from dataclasses import dataclass
from fnmatch import fnmatchcase
from typing import NamedTuple


@dataclass(frozen=True)
class Watch:
    variable: str  # an output, or a glob of outputs (`*` for a joint's or shaft's number)
    limit: str | float  # a parameter's name, or a value in the output's unit
    message: str  # what passing the limit means to an engineer


@dataclass(frozen=True)
class WatchedOutput:
    """One watch compiled for a table: the output's slot among the outputs."""

    slot: int
    name: str
    unit: str
    limit: str | float
    message: str


def compile_watches(watches, table) -> tuple[WatchedOutput, ...]:
    """The outputs `watches` name in `table`, in table order. A row whose output
    or limit parameter the table lacks (a build without them) watches nothing."""
    compiled = []
    for watch in watches:
        if isinstance(watch.limit, str) and watch.limit not in table.PARAMETERS:
            continue
        for slot, name in enumerate(table.OUTPUTS):
            if fnmatchcase(name, watch.variable):
                unit = table.BY_NAME[name].unit
                compiled.append(WatchedOutput(slot, name, unit, watch.limit, watch.message))
    return tuple(compiled)


class Armed(NamedTuple):
    """The watches not yet passed: (output slot, limit) of each, and its row."""

    checks: tuple[tuple[int, float], ...]
    watches: tuple[WatchedOutput, ...]


def arm(watched, model, fired=()) -> "Armed | tuple[()]":
    """The watched outputs not in `fired` (names), each limit read from `model`'s
    parameters now (they are fixed after initialization); () when none is left.
    A limit that is not a number watches nothing."""
    kept = []
    for watch in watched:
        limit = watch.limit
        value = float(getattr(model, limit) if isinstance(limit, str) else limit)
        if watch.name not in fired and not math.isnan(value):
            kept.append((watch, value))
    return _armed(kept)


def _armed(kept) -> "Armed | tuple[()]":
    """Armed of (watch, limit) pairs; () for none (falsy: the step skips the check)."""
    if not kept:
        return ()
    return Armed(tuple((w.slot, v) for w, v in kept), tuple(w for w, _ in kept))


def any_passed(armed: Armed, outputs) -> bool:
    """Whether an armed output is past its limit: the check after every step
    (a plain loop: CPython runs it faster than map and any)."""
    for slot, limit in armed.checks:
        if abs(outputs[slot]) > limit:
            return True
    return False


def passed(armed, outputs, time: float) -> "tuple[Armed | tuple[()], list[str]]":
    """(the watches still armed, a message for each output past its limit now)."""
    if not armed or not any_passed(armed, outputs):
        return armed, []
    messages, kept = [], []
    for (slot, limit), watch in zip(armed.checks, armed.watches):
        value = outputs[slot]
        if abs(value) > limit:
            messages.append(_message(watch, value, limit, time))
        else:
            kept.append((watch, limit))
    return _armed(kept), messages


def armed_names(armed) -> set[str]:
    """The names of the watches `armed` still holds."""
    return {watch.name for watch in armed.watches} if armed else set()


def _message(watch: WatchedOutput, value: float, limit: float, time: float) -> str:
    unit = "" if watch.unit == "1" else f" {watch.unit}"
    named = f"{watch.limit} = " if isinstance(watch.limit, str) else ""
    return (
        f"{watch.name} = {value:.6g}{unit} at t = {float(f'{time:.12g}')!r} s is past "
        f"{named}{limit:.6g}{unit}: {watch.message} (warned once; the run goes on)"
    )
