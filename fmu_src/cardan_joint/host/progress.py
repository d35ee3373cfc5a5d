"""The progress bar of a long run (tqdm), for `simulate`, the command line and
the examples alike.

A run of PROGRESS_MIN_STEPS steps or more shows one, on a terminal only: in a
log file or a pipe tqdm's `disable=None` draws nothing, so a log never fills
with bars. `progress=True` draws it whatever the run and the stream,
`progress=False` never. The bar is made at the first step (none for a run
refused before it starts) and closed however the run ends.
"""

from typing import Any

# Runs with fewer steps finish before a progress bar would help (about a second).
PROGRESS_MIN_STEPS = 20_000


class StepProgress:
    """`update(time)` after each step of a run of `steps` steps of `step` s."""

    def __init__(self, steps: int, step: float, progress: bool | None = None) -> None:
        self.steps, self.step = steps, step
        # tqdm's disable=None: only on a terminal.
        self.disable = {True: False, None: None}.get(progress, True)
        if progress is None and steps < PROGRESS_MIN_STEPS:
            self.disable = True
        self._bar: Any = None

    def update(self, time: float) -> None:
        if self.disable is True:
            return
        if self._bar is None:
            from tqdm import tqdm

            self._bar = tqdm(total=self.steps, desc="simulate", unit="step", disable=self.disable)
        self._bar.update(min(self.steps, round(time / self.step)) - self._bar.n)

    def close(self) -> None:
        if self._bar is not None:
            self._bar.close()
