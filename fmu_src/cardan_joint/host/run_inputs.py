"""The inputs of a run: input CSVs, `--set` pairs split into inputs and
parameters, and the one input signal for FMPy, every mistake a `UsageError`
naming it. Names and units come from the FMU (`FmuInfo`), so this serves
every model: a value is in the variable's SI unit, or in a unit written after
it (`--set bend_angle=20deg`, a column titled `input_speed [rpm]`) that is the
SI unit or one of the display units the FMU declares.

FMPy prints `Warning: missing input for variable ...` for every input without
a signal. An input nobody sets is not undefined for these FMUs: it holds its
start value, or (speed, bend angle, bend angle rate) is carried along its rate
over each step. `complete_inputs` gives each missing input exactly that
signal, so completing the inputs changes nothing but the noise.
"""

import re
from typing import Any

import numpy as np

from .. import results
from ..names import UsageError
from .fmu_info import FmuInfo

# Inputs the FMU carries along a rate when no one sets them (see "Step semantics").
RATES = {
    "input_speed": ("input_acceleration",),
    "bend_angle_rate": ("bend_angle_acceleration",),
    "bend_angle": ("bend_angle_rate", "bend_angle_acceleration"),
}


# A value with an optional unit after it: "0.3", "20deg", "1500 rpm", "-1e3rad/s2".
_QUANTITY = re.compile(
    r"\s*([-+]?(?:(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?|inf|nan))\s*(.*?)\s*$", re.IGNORECASE
)


def units_of(info: FmuInfo, name: str) -> dict[str, tuple[float, float]]:
    """{unit: (factor, offset)} a value of `name` may be given in (display = SI *
    factor + offset): its SI unit and the display units the FMU declares for it."""
    unit = info.variables[name].unit
    units = {unit: (1.0, 0.0)} if unit else {}
    for definition in info.model_description.unitDefinitions:
        if definition.name == unit:
            units.update(
                (d.name, (float(d.factor), float(d.offset or 0.0))) for d in definition.displayUnits
            )
    return units


def in_si(info: FmuInfo, name: str, value: Any, unit: str, where: str) -> Any:
    """`value` (a number or an array) of `name` given in `unit` (SI if empty)
    as the FMU's SI value; UsageError naming the units it takes."""
    if not unit:
        return value
    units = units_of(info, name)
    if unit not in units:
        taken = " or ".join(units) or "no unit (a plain number)"
        raise UsageError(f"{where}: {name} takes {taken}, not {unit!r}")
    factor, offset = units[unit]
    return (value - offset) / factor


def parse_set(pairs, info: FmuInfo) -> dict[str, float]:
    """--set NAME=VALUE[UNIT] ... -> {NAME: SI value}; UNIT (`20deg`, `1500rpm`)
    is the variable's SI unit or one of its display units, none meaning SI."""
    texts = {}
    for pair in pairs:
        name, sep, text = pair.partition("=")
        if not sep or not name.strip():
            raise UsageError(f"--set takes NAME=VALUE, got {pair!r}")
        texts[name.strip()] = (pair, text)
    info.check(texts, ("input", "parameter"), "input or parameter")
    values = {}
    for name, (pair, text) in texts.items():
        match = _QUANTITY.fullmatch(text)
        if match is None:
            raise UsageError(f"--set {pair}: {text.strip()!r} is not a number (with a unit)")
        values[name] = in_si(info, name, float(match[1]), match[2], f"--set {pair}")
    return values


def split_assignments(pairs, info: FmuInfo) -> tuple[dict[str, float], dict[str, float]]:
    """--set NAME=VALUE[UNIT] ... -> (constant inputs, parameter start values), in SI."""
    values = parse_set(pairs, info)
    inputs = {n: v for n, v in values.items() if info.variables[n].causality == "input"}
    return inputs, {n: v for n, v in values.items() if n not in inputs}


def read_input_csv(path, info: FmuInfo):
    """A CSV with a `time` column and input-name columns -> FMPy's structured array."""
    try:
        signal, units = results.read_csv_units(path)
    except results.ResultFileError as error:
        raise UsageError(f"input file {error}") from None
    header = list(signal.dtype.names or ())
    if "time" not in header:
        raise UsageError(f"{path}: no 'time' column (columns: {', '.join(header)})")
    columns = [n for n in header if n != "time"]
    parameters = [n for n in columns if n in info.names("parameter")]
    if parameters:
        raise UsageError(
            f"{path}, column {parameters[0]!r}: a parameter is fixed for the run; "
            f"set it with --set {parameters[0]}=VALUE"
        )
    try:
        info.check(columns, ("input",), "input")
    except UsageError as error:
        raise UsageError(f"{path}: {error}") from None
    for name in header:
        if not np.all(np.isfinite(signal[name])):
            raise UsageError(f"{path}, column {name!r}: every value must be a finite number")
    for name, unit in units.items():
        if name == "time":
            if unit != "s":
                raise UsageError(f"{path}, column 'time': time is given in s, not {unit!r}")
            continue
        signal[name] = in_si(info, name, signal[name], unit, f"{path}, column {name!r}")
    times = signal["time"]
    if np.any(np.diff(times) < 0):
        raise UsageError(f"{path}: the time column must be non-decreasing")
    return signal


def with_constants(signal: np.ndarray, constants: dict[str, float]) -> np.ndarray:
    """An input CSV's signal with constant columns added (from --set)."""
    names = signal.dtype.names or ()
    clash = sorted(set(names) & set(constants))
    if clash:
        raise UsageError(f"{', '.join(clash)} given both by --set and in the input CSV")
    merged = np.zeros(len(signal), dtype=signal.dtype.descr + [(n, float) for n in constants])
    for name in merged.dtype.names or ():
        merged[name] = signal[name] if name in names else constants[name]
    return merged


def _constant(inputs, name: str, starts: dict) -> float | None:
    """The value of an input held constant over the run (given or left at its start), else None."""
    if isinstance(inputs, dict) or name not in inputs.dtype.names:
        source = inputs if isinstance(inputs, dict) and name in inputs else starts
        return float(source.get(name, 0.0))
    column = inputs[name]
    return float(column[0]) if len(column) and np.all(column == column[0]) else None


def _refuse_contradictions(inputs, rates: dict, starts: dict) -> None:
    """A value given as a constant while its rate is a nonzero constant: the FMU
    would restart it at the constant every step (a saw-tooth), not a run anyone means."""
    given = set(inputs) if isinstance(inputs, dict) else set(inputs.dtype.names)
    for name, (rate, *_) in rates.items():
        value, slope = _constant(inputs, name, starts), _constant(inputs, rate, starts)
        if name in given and value is not None and slope:
            raise UsageError(
                f"{name} = {value:g} is given as a constant while {rate} = {slope:g} "
                f"(nonzero): contradictory; give {name} as a signal that follows "
                f"{rate}, or leave {name} out and the FMU carries it along {rate}"
            )


def _refuse_unrated_ramps(signal: np.ndarray, rates: dict, starts: dict) -> None:
    """A column that ramps while its rate is left at a value the ramp does not
    have (no rate column): the FMU would carry it along that rate within each
    step and jump back at the next, so its outputs (the acceleration) would
    contradict the value. `--set` refuses the same contradiction for constants."""
    given = set(signal.dtype.names or ())
    times = signal["time"]
    for name, (rate, *_) in rates.items():
        if name not in given or rate in given or len(times) < 2:
            continue
        spans = np.diff(times)
        moving = spans > 0
        slopes = np.diff(signal[name])[moving] / spans[moving]
        held = float(starts[rate])
        wrong = np.abs(slopes - held) > 1e-9 * np.maximum(np.abs(slopes), 1.0)
        if np.any(wrong):
            k = int(np.argmax(wrong))
            start, end = times[:-1][moving][k], times[1:][moving][k]
            raise UsageError(
                f"{name} ramps at {slopes[k]:g} per s from t = {start:g} s to {end:g} s "
                f"while {rate} is held at {held:g} (no {rate} column): contradictory; "
                f"give a {rate} column that follows the ramp (or --set {rate}=VALUE "
                f"for a single ramp)"
            )


def complete_inputs(inputs, starts: dict, stop_time: float, step: float) -> np.ndarray:
    """`inputs` (dict of constants or structured array) with a signal for every
    input of the FMU (`starts`: input name -> start value), each missing one
    following what the FMU does with it left unset: held at its start value,
    or carried along its rate."""
    # Only the carried inputs this FMU has (not every model has a bend angle).
    rates = {n: r for n, r in RATES.items() if n in starts and set(r) <= set(starts)}
    _refuse_contradictions(inputs, rates, starts)
    if not isinstance(inputs, dict):
        _refuse_unrated_ramps(inputs, rates, starts)
    names = tuple(name for name in starts if name not in rates) + tuple(rates)
    if not isinstance(inputs, dict):
        given = set(inputs.dtype.names)
        moving = {
            n
            for n in names
            if n not in given and any(r in given or starts[r] != 0.0 for r in rates.get(n, ()))
        }
        if moving:
            return inputs  # the FMU carries these along given rates: leave them unset
        signal = np.zeros(
            len(inputs), dtype=inputs.dtype.descr + [(n, float) for n in names if n not in given]
        )
        for name in signal.dtype.names:
            signal[name] = inputs[name] if name in given else starts[name]
        return signal
    value = {name: float(inputs.get(name, starts[name])) for name in names}
    # Linear pieces are exact between two points; a bend angle carried by its
    # acceleration is a parabola, given at every communication point.
    curved = (
        "bend_angle" in rates
        and "bend_angle" not in inputs
        and value["bend_angle_acceleration"] != 0.0
    )
    t = (
        np.linspace(0.0, stop_time, max(1, round(stop_time / step)) + 1)
        if curved
        else np.array([0.0, stop_time])
    )
    signal = np.zeros(len(t), dtype=[("time", float)] + [(n, float) for n in names])
    signal["time"] = t
    for name in names:
        signal[name] = value[name]
    if "input_speed" in rates and "input_speed" not in inputs:
        signal["input_speed"] = value["input_speed"] + value["input_acceleration"] * t
    if "bend_angle_rate" in rates and "bend_angle_rate" not in inputs:
        signal["bend_angle_rate"] = value["bend_angle_rate"] + value["bend_angle_acceleration"] * t
    if "bend_angle" in rates and "bend_angle" not in inputs:
        signal["bend_angle"] = (
            value["bend_angle"]
            + value["bend_angle_rate"] * t
            + 0.5 * value["bend_angle_acceleration"] * t * t
        )
    return signal
