"""Duty cycles read from a file: a measured time series or a block table
(load-duration table), both as the steps an FMU is driven through (docs/life.md).

A time series (CSV or Parquet): `time`, `input_speed`, a torque (`load_torque`,
`input_torque` or `torque`), `bend_angle`, and optionally the rates
`input_acceleration`, `bend_angle_rate`, `bend_angle_acceleration`. A block
table (CSV): optional `block` names, `time_share` or `revolution_share`,
`speed`, `torque`, `angle`. A column may carry its unit in brackets
(`input_speed [rpm]`, `angle [deg]`, `time_share [%]`); a time series' bare
names are SI (s, rad/s, N.m, rad), a block table names the units of its speed
and angle. Each sample interval of a time series is one step: a missing rate
is the segment's slope from its sample, so the step's polynomial is exact for
piecewise-linear speed and angle; the torque, which the FMU holds over a step,
is held at its sample.
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from ..names import UsageError
from ..units import DEG_TO_RAD, RPM_TO_RAD_PER_S

# A unit in a header -> (the SI unit it converts into, its factor into it).
UNITS = {
    "s": ("s", 1.0),
    "min": ("s", 60.0),
    "h": ("s", 3600.0),
    "rad/s": ("rad/s", 1.0),
    "rpm": ("rad/s", RPM_TO_RAD_PER_S),
    "deg/s": ("rad/s", DEG_TO_RAD),
    "rad/s2": ("rad/s2", 1.0),
    "rpm/s": ("rad/s2", RPM_TO_RAD_PER_S),
    "deg/s2": ("rad/s2", DEG_TO_RAD),
    "rad": ("rad", 1.0),
    "deg": ("rad", DEG_TO_RAD),
    "N.m": ("N.m", 1.0),
    "kN.m": ("N.m", 1e3),
    "1": ("1", 1.0),
    "%": ("1", 0.01),
}
# Each column a cycle may have -> its SI unit (the unit of a bare name in a time series).
COLUMNS = {
    "time": "s",
    "input_speed": "rad/s",
    "input_acceleration": "rad/s2",
    "load_torque": "N.m",
    "input_torque": "N.m",
    "torque": "N.m",
    "bend_angle": "rad",
    "bend_angle_rate": "rad/s",
    "bend_angle_acceleration": "rad/s2",
    "speed": "rad/s",
    "angle": "rad",
    "time_share": "1",
    "revolution_share": "1",
}
_HEADER = re.compile(r"^\s*([A-Za-z_][A-Za-z0-9_]*)\s*(?:\[\s*([^\]]*?)\s*\])?\s*$")
TORQUES = ("load_torque", "input_torque", "torque")
SHARES = ("time_share", "revolution_share")


@dataclass(frozen=True)
class DutyCycle:
    """The steps of a cycle: each step i from `times[i]` for `steps[i]` s with
    the inputs in `inputs` (name -> per-step values), in part `part[i]` (a
    block, or a span of a time series) named `labels[part[i]]`."""

    kind: str  # "blocks" or "time series"
    source: str
    times: np.ndarray
    steps: np.ndarray
    inputs: dict[str, np.ndarray]
    part: np.ndarray
    labels: tuple[str, ...]

    @property
    def seconds(self) -> float:
        return math.fsum(self.steps)

    @property
    def has_angle(self) -> bool:
        return "bend_angle" in self.inputs


def _read_frame(path: Path):
    import pandas as pd

    if not path.is_file():
        raise UsageError(f"{path} does not exist")
    if path.suffix.lower() == ".parquet":
        from ..extras import require

        require("pyarrow", "parquet", "reading a Parquet duty cycle")
        return pd.read_parquet(path)
    try:
        return pd.read_csv(path, skipinitialspace=True, comment="#")
    except (pd.errors.EmptyDataError, pd.errors.ParserError, UnicodeDecodeError) as error:
        raise UsageError(f"{path}: not a table under one header line ({error})") from None


def _columns(path: Path, frame, text=("block",)) -> dict[str, np.ndarray]:
    """Column name -> values in SI, each unit checked against its quantity."""
    columns: dict[str, np.ndarray] = {}
    for header in frame.columns:
        match = _HEADER.match(str(header))
        if not match:
            raise UsageError(f"{path}: column {header!r}: write NAME or NAME [unit]")
        name, unit = match.group(1), match.group(2)
        if name in text:
            columns[name] = frame[header].astype(str).to_numpy()
            continue
        if name not in COLUMNS:
            raise UsageError(
                f"{path}: unknown column {name!r} (columns: {', '.join(COLUMNS)}, block)"
            )
        si, factor = COLUMNS[name], 1.0
        if unit is not None:
            if UNITS.get(unit, ("",))[0] != si:
                units = ", ".join(u for u, (to, _) in UNITS.items() if to == si)
                raise UsageError(f"{path}: column {name!r} in [{unit}]: give it in {units}")
            factor = UNITS[unit][1]
        values = np.asarray(frame[header], dtype=object)
        try:
            numbers = np.array([float(v) for v in values])
        except (TypeError, ValueError):
            raise UsageError(f"{path}: column {name!r} holds a value that is no number") from None
        if not np.all(np.isfinite(numbers)):
            raise UsageError(f"{path}: column {name!r}: every value must be a finite number")
        columns[name] = numbers * factor
    return columns


def _one_torque(path: Path, columns) -> np.ndarray:
    given = [name for name in TORQUES if name in columns]
    if len(given) != 1:
        raise UsageError(f"{path}: give one torque column, one of {', '.join(TORQUES)}")
    return columns[given[0]]


def slopes(times: np.ndarray, values: np.ndarray) -> np.ndarray:
    """Each segment's slope, from its first sample: the rate that makes a step
    over the segment exact for piecewise-linear `values`."""
    return np.diff(values) / np.diff(times)


def read_time_series(path: str | Path, spans: int = 10, frame=None) -> DutyCycle:
    """A measured series: one step per sample interval, in `spans` equal spans."""
    path = Path(path)
    columns = _columns(path, _read_frame(path) if frame is None else frame)
    for needed in ("time", "input_speed"):
        if needed not in columns:
            raise UsageError(f"{path}: no {needed!r} column")
    times, torque = columns["time"], _one_torque(path, columns)
    if len(times) < 2 or np.any(np.diff(times) <= 0.0):
        raise UsageError(f"{path}: the time column must rise from sample to sample")
    first = slice(0, -1)  # each step's inputs are those of its first sample
    speed = columns["input_speed"]
    acceleration = columns.get("input_acceleration", np.append(slopes(times, speed), 0.0))
    inputs = {
        "input_speed": speed[first],
        "input_acceleration": acceleration[first],
        "load_torque": torque[first],
    }
    if "bend_angle" in columns:
        angle = columns["bend_angle"]
        rate = columns.get("bend_angle_rate", np.append(slopes(times, angle), 0.0))
        inputs["bend_angle"] = angle[first]
        inputs["bend_angle_rate"] = rate[first]
        inputs["bend_angle_acceleration"] = columns.get(
            "bend_angle_acceleration", np.zeros(len(times))
        )[first]
    part, labels = _spans(times, spans)
    return DutyCycle("time series", str(path), times[first], np.diff(times), inputs, part, labels)


def _spans(times: np.ndarray, spans: int) -> tuple[np.ndarray, tuple[str, ...]]:
    """Each step's span (by its start: `spans` equal spans of time, those holding
    no step start left out) and each span's label, the times its steps cover."""
    relative = (times[:-1] - times[0]) / (times[-1] - times[0]) * spans
    # A start on a boundary (up to rounding) opens the next span.
    index = np.minimum(np.floor(relative + 1e-9).astype(int), spans - 1)
    used, part = np.unique(index, return_inverse=True)
    labels = []
    for k in range(len(used)):
        steps = np.flatnonzero(part == k)
        labels.append(f"{times[steps[0]]:.6g}-{times[steps[-1] + 1]:.6g} s")
    return part, tuple(labels)


def read_block_table(
    path: str | Path, cycle_time: float = 10.0, step: float = 1e-3, frame=None
) -> DutyCycle:
    """A catalogue's block table, as `cycle_time` s of driving in steps of at most `step` s."""
    path = Path(path)
    frame = _read_frame(path) if frame is None else frame
    columns = _columns(path, frame)
    for name in ("speed", "angle"):
        if name in columns and "[" not in _header(frame, name):
            raise UsageError(f"{path}: column {name!r}: give its unit, e.g. '{name} [rpm|deg]'")
    if "speed" not in columns:
        raise UsageError(f"{path}: no 'speed' column")
    shares = [name for name in SHARES if name in columns]
    if len(shares) != 1:
        raise UsageError(f"{path}: give one share column, time_share or revolution_share")
    share, speed, torque = columns[shares[0]], columns["speed"], _one_torque(path, columns)
    if np.any(share < 0.0) or not math.isclose(share.sum(), 1.0, rel_tol=1e-6):
        raise UsageError(f"{path}: the {shares[0]}s must be >= 0 and add up to 1 (100 %)")
    if shares[0] == "revolution_share":
        if np.any((share > 0) & (speed == 0.0)):
            raise UsageError(f"{path}: a block with a revolution share needs a speed")
        time = np.divide(share, np.abs(speed), out=np.zeros_like(share), where=share > 0)
        share = time / time.sum()
    names = columns.get("block", np.array([f"block {i + 1}" for i in range(len(share))]))
    counts = [max(1, math.ceil(q * cycle_time / step - 1e-9)) if q > 0 else 0 for q in share]
    durations = np.repeat(share * cycle_time / np.maximum(counts, 1), counts)
    part = np.repeat(np.arange(len(share)), counts)
    inputs = {"input_speed": speed[part], "input_acceleration": np.zeros(len(part))}
    inputs["load_torque"] = torque[part]
    if "angle" in columns:
        inputs["bend_angle"] = columns["angle"][part]
        inputs["bend_angle_rate"] = inputs["bend_angle_acceleration"] = np.zeros(len(part))
    times = np.concatenate(([0.0], np.cumsum(durations)[:-1]))
    return DutyCycle("blocks", str(path), times, durations, inputs, part, tuple(map(str, names)))


def _header(frame, name: str) -> str:
    return next(str(h) for h in frame.columns if str(h).split("[")[0].strip() == name)


def read_duty_cycle(path: str | Path, cycle_time: float = 10.0, step: float = 1e-3, spans=10):
    """A block table if the file has a share column, else a time series."""
    frame = _read_frame(Path(path))
    names = {str(h).split("[")[0].strip() for h in frame.columns}
    if names & set(SHARES):
        return read_block_table(path, cycle_time, step, frame)
    return read_time_series(path, spans, frame)
