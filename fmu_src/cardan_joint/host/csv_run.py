"""A run streamed to a CSV as it goes: memory stays bounded however long the run.

The rows go to the CSV in chunks (FMI 3 arrays split into their FMI 2 columns),
each column titled with its SI unit (`output_speed [rad/s]`), under a
temporary name that becomes the file only when the run is over: a run
that finished or was refused after its first step leaves a whole CSV of what
it computed; an interrupted or failed one leaves no file (and an earlier file
of that name untouched). At most `plot_rows` rows are kept for a figure: every
row, or of a longer run each group's least and greatest (`StreamedRun`).
Before the first step, the CSV's size is checked against the free space of
its file system.
"""

import math
from collections.abc import Mapping, Sequence
from pathlib import Path
from typing import Any

import numpy as np

from ..results import CsvStream
from .fmu_info import FmuInfo
from .run_arguments import check_disk
from .simulate import (
    SimulationError,
    flat_columns,
    recorded_values,
    recorded_variables,
    run_times,
    simulate,
)

# Enough rows for a sharp figure of any size; more only slow the plot down.
PLOT_ROWS = 100_000


def plot_stride(rows: int, plot_rows: int = PLOT_ROWS) -> int:
    """Rows per kept group of a run of `rows` rows: 1 (every row kept) up to
    `plot_rows`, else as many as keep two rows (least, greatest) per group within it."""
    return 1 if rows <= plot_rows else math.ceil(2 * rows / plot_rows)


class StreamedRun:
    """`rows_to` of `simulate`: writes each chunk, keeps every row (`stride` 1)
    or, for each group of `stride` rows, two: each column's least and greatest
    value in the group (a figure's envelope then holds every peak of the run,
    which every `stride`-th row alone would miss)."""

    def __init__(self, path: Path, stride: int, units: Mapping[str, str] | None = None) -> None:
        self.path, self.stride, self.units = Path(path), stride, units
        self.stream: CsvStream | None = None
        self._kept: list[np.ndarray] = []
        self._last: np.ndarray | None = None  # the last row, drawn whatever the stride

    def __call__(self, rows: np.ndarray) -> None:
        rows = flat_columns(rows)
        if self.stream is None:
            self.stream = CsvStream(self.path, rows.dtype.names or (), self.units)
        offset = self.stream.rows  # the groups continue across chunks
        self.stream.write(rows)
        self._kept.append(rows if self.stride == 1 else self._extremes(rows, offset))
        self._last = rows[-1:] if self.stride > 1 else None

    def _extremes(self, rows: np.ndarray, offset: int) -> np.ndarray:
        """Each group's least and greatest row, column by column, interleaved (a
        group cut by the chunk's edge gives a pair on either side)."""
        starts = np.union1d([0], np.arange(-offset % self.stride, len(rows), self.stride))
        kept = np.zeros(2 * len(starts), dtype=rows.dtype)
        for name in rows.dtype.names or ():
            kept[name][0::2] = np.fmin.reduceat(rows[name], starts)
            kept[name][1::2] = np.fmax.reduceat(rows[name], starts)
        return kept

    @property
    def rows(self) -> int:
        return self.stream.rows if self.stream is not None else 0

    def sample(self) -> np.ndarray:
        """The rows kept for a figure (in time order): every row, or each group's
        least and greatest and the last row."""
        kept = self._kept + ([self._last] if self._last is not None else [])
        return np.concatenate(kept) if kept else np.zeros(0, [("time", float)])

    def commit(self) -> Path:
        if self.stream is None:
            raise ValueError(f"no rows to write to {self.path}")
        return self.stream.commit()

    def discard(self) -> None:
        if self.stream is not None:
            self.stream.discard()


def column_units(info: FmuInfo) -> dict[str, str]:
    """{column: SI unit} of a run's CSV: the time's and every variable's (FMI 2 columns)."""
    units = {c: v.unit for v in info.variables.values() for c in v.columns}
    return {**units, "time": "s"}


def simulate_to_csv(
    fmu: str | Path | FmuInfo,
    path: str | Path,
    stop_time: float | None = None,
    output_interval: float | None = None,
    inputs: np.ndarray | Mapping[str, float] | None = None,
    start_values: Mapping[str, float] | None = None,
    output: Sequence[str] | None = None,
    plot_rows: int = PLOT_ROWS,
    run: StreamedRun | None = None,
    **options: Any,
) -> StreamedRun:
    """`simulate` with every row written to the CSV `path` as the run goes;
    returns the StreamedRun (`rows` written, `sample()` for a figure; pass your
    own `run` to keep it when the run raises). A refused run writes the rows up
    to the refusal (none if refused at its start: then no file) and raises the
    SimulationError; Ctrl-C or any other error writes nothing. RunTooLargeError,
    before the first step, when the CSV would not fit on its file system."""
    info = fmu if isinstance(fmu, FmuInfo) else FmuInfo.read(fmu)
    length = run_times(info, stop_time, output_interval)
    check_disk(length, recorded_values(info, recorded_variables(info, output)), Path(path))
    if run is None:
        run = StreamedRun(Path(path), plot_stride(length.rows, plot_rows), column_units(info))
    try:
        try:
            simulate(
                info,
                stop_time=stop_time,
                output_interval=output_interval,
                inputs=inputs,
                start_values=start_values,
                output=output,
                rows_to=run,
                **options,
            )
        except SimulationError:
            if run.rows > 1:  # a step was taken: what it computed is a result
                run.commit()
            raise
        run.commit()
    except BaseException:  # refused at the start, Ctrl-C (even while committing), any error
        run.discard()  # after a commit: nothing left to remove
        raise
    return run
