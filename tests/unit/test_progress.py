"""The progress bar of a long run (host/progress.py): shown on a terminal from
PROGRESS_MIN_STEPS steps on, never into a log file or a pipe, always when asked."""

import io
import sys

import pytest

from cardan_joint.host.progress import PROGRESS_MIN_STEPS, StepProgress


class Terminal(io.StringIO):
    def isatty(self) -> bool:
        return True


def _drawn(monkeypatch, stream, steps, progress) -> str:
    monkeypatch.setattr(sys, "stderr", stream)
    bar = StepProgress(steps, 1e-3, progress)
    for k in range(1, 4):
        bar.update(k * 1e-3)
    bar.close()
    return stream.getvalue()


@pytest.mark.parametrize(
    "terminal, steps, progress, shown",
    [
        (True, PROGRESS_MIN_STEPS, None, True),  # a long run on a terminal
        (True, PROGRESS_MIN_STEPS - 1, None, False),  # too short to need one
        (False, 10 * PROGRESS_MIN_STEPS, None, False),  # a log file or a pipe
        (False, 10, True, True),  # --progress: always
        (True, 10 * PROGRESS_MIN_STEPS, False, False),  # --no-progress: never
    ],
)
def test_a_bar_is_drawn_on_a_terminal_for_a_long_run_only(
    monkeypatch, terminal, steps, progress, shown
):
    stream = Terminal() if terminal else io.StringIO()
    drawn = _drawn(monkeypatch, stream, steps, progress)
    assert ("simulate:" in drawn) == shown, drawn
    if shown:
        assert f"3/{steps}" in drawn
