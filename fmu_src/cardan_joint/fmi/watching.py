"""The slave's side of the watches (`framework.watches`): armed when
initialization ends, checked after each taken step, kept in the FMU state.

Each watched output past its limit is logged once per instance, as a warning
in the category `logWatch`, naming the output, its value, the limit and the
time; the step is taken and the run goes on (the loader returns the step's
status as the worst logged: Warning). A reset makes a new slave: every watch
armed again. A set FMU state brings back the watches as they were when it was
got: a run taken back to before a warning warns again if it passes again.
"""

import math
from collections.abc import Callable
from typing import Any

from ..framework.watches import arm, armed_names, compile_watches, passed
from .references import WATCH_CATEGORY


class Watching:
    """Mixed into `core.SlaveCore`, whose model, status and `_report` these use."""

    table: Any
    watches: tuple = ()  # the model's `framework.watches.Watch` rows (its spec's)
    _watched: tuple = ()  # compiled for the table: output slots
    _armed: Any = ()  # `framework.watches.Armed`: not yet passed; () before initialization
    _initialized: bool
    _model: Any
    _STATUS: Any
    _report: Callable[..., None]  # (message, status, category)

    def __init_subclass__(cls, **kwargs):
        super().__init_subclass__(**kwargs)
        if cls.table is not None:
            cls._watched = compile_watches(cls.watches, cls.table)

    def _watching(self) -> bool:
        """Steps can be taken: initialized, with parameters that can run."""
        return self._initialized and not self._model.parameter_fault

    def _rearm(self, passed_already=()) -> None:
        """Arm every watch not in `passed_already` (names), its limit read now."""
        self._armed = arm(self._watched, self._model, passed_already) if self._watching() else ()

    def _watch(self, outputs) -> None:
        """After a taken step (with watches armed): warn once of each watched
        output past its limit."""
        self._armed, messages = passed(self._armed, outputs, self._model.time)
        for message in messages:
            self._report(message, self._STATUS.warning, WATCH_CATEGORY)

    def _watch_limits(self) -> tuple[float, ...]:
        """Each output's smallest armed limit, inf where none is armed: what a
        step in C compares its outputs with (`fast_path.py`). The smallest, as
        several watches of one output must hand over at the first one passed."""
        limits = [math.inf] * len(self.table.OUTPUTS)
        for slot, limit in self._armed.checks if self._armed else ():
            limits[slot] = min(limits[slot], limit)
        return tuple(limits)

    def _watches_passed(self) -> list[str]:
        """The watched outputs already warned of, for the FMU state."""
        armed = armed_names(self._armed)
        return [w.name for w in self._watched if w.name not in armed] if self._watching() else []
